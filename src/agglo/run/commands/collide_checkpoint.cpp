// Checkpoints of agglo collide (collide_checkpoint.hpp).
#include "agglo/run/commands/collide_checkpoint.hpp"

#include <cmath>

#include "agglo/io/impact_checkpoint.hpp"

namespace agglo::run {

CollideCheckpoints::CollideCheckpoints(const Config& cfg, const OutputDir& out, const RunContext& ctx)
    : out_(out), ctx_(ctx) {
  header_.command = "collide";
  header_.config_hash = io::config_hash(cfg.resolved_toml());
}

std::optional<impact::ImpactState> CollideCheckpoints::resume_state() const {
  if (!ctx_.resume) return std::nullopt;  // a killed writer's checkpoint.bin.tmp-<pid>: removed by OutputDir
  if (!io::has_checkpoint(out_)) return std::nullopt;
  io::CheckpointHeader found;
  auto reader = io::read_checkpoint(out_, header_, found);
  return io::read_impact_state(reader);
}

void CollideCheckpoints::at_boundary(const impact::ImpactRun& run) {
  const double interval = ctx_.checkpoint_interval;
  if (ctx_.cancel && ctx_.cancel->cancelled()) {
    if (interval > 0.0) save(run);
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
  io::write_impact_state(w, run.state());
  header_.step = static_cast<std::uint64_t>(run.steps());
  header_.time = run.since_launch();
  io::write_checkpoint(out_, header_, w.bytes());
}

}  // namespace agglo::run
