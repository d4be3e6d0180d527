// Checkpoints of agglo collide (collide_checkpoint.hpp).
#include "agglo/run/commands/collide_checkpoint.hpp"

#include <cmath>

#include "agglo/impact/checkpoint.hpp"

namespace agglo::run {

CollideCheckpoints::CollideCheckpoints(const Command& collide, const Config& cfg, const OutputDir& out,
                                       const RunContext& ctx)
    : ctx_(ctx), io_(checkpoint_io(collide, cfg, out, ctx)) {}

std::optional<impact::ImpactState> CollideCheckpoints::resume_state() {
  if (!io_.resume) return std::nullopt;  // a killed writer's checkpoint.bin.tmp-<pid>: removed by OutputDir
  return impact::read_impact_state(*io_.resume);
}

void CollideCheckpoints::at_boundary(const impact::ImpactRun& run) {
  const double interval = ctx_.checkpoint_interval;
  if (ctx_.cancel && ctx_.cancel->cancelled()) {
    save(run);  // also without --checkpoint: --resume continues an interrupted run (docs/restart.md)
    throw_if_cancelled(ctx_.cancel);
  }
  if (interval <= 0.0) return;
  const auto multiple = static_cast<long long>(std::floor(run.since_launch() / interval));
  if (last_multiple_ < 0) last_multiple_ = multiple;  // the launch, or the state resumed from
  if (multiple > last_multiple_) {
    last_multiple_ = multiple;
    save(run);
  }
}

void CollideCheckpoints::at_end(const impact::ImpactRun& run) {
  if (ctx_.checkpoint_interval > 0.0) save(run);
}

void CollideCheckpoints::save(const impact::ImpactRun& run) {
  io::CheckpointWriter w;
  impact::write_impact_state(w, run.state());
  io_.write(static_cast<std::uint64_t>(run.steps()), run.since_launch(), w.bytes());
}

}  // namespace agglo::run
