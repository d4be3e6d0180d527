#pragma once
// Checkpoints of `agglo collide` (docs/restart.md, "Collide"): with --checkpoint INTERVAL a checkpoint of the
// whole collision state (io/impact_checkpoint.hpp) is written each time the simulated time since
// launch crosses a multiple of INTERVAL, when the run is interrupted (at the step boundary where the
// cancellation is seen) and at the end. Under --resume the run continues from the folder's checkpoint
// (none: from the launch); a checkpoint of another build or config is refused (ConfigError).
#include <optional>

#include "agglo/core/config.hpp"
#include "agglo/impact/impact_run.hpp"
#include "agglo/io/checkpoint.hpp"
#include "agglo/run/command.hpp"

namespace agglo::run {

class CollideCheckpoints {
 public:
  CollideCheckpoints(const Config& cfg, const OutputDir& out, const RunContext& ctx);
  // The state to continue from under --resume when the folder has a checkpoint.
  std::optional<impact::ImpactState> resume_state() const;
  // Called at every step boundary: checkpoint when due; on cancellation checkpoint (with an interval)
  // and throw InterruptedError.
  void at_boundary(const impact::ImpactRun& run);
  // The checkpoint of the final state (with an interval).
  void at_end(const impact::ImpactRun& run);

 private:
  void save(const impact::ImpactRun& run);
  const OutputDir& out_;
  const RunContext& ctx_;
  io::CheckpointHeader header_;
  long long last_multiple_ = -1;  // of the interval, reached at the last boundary
};

}  // namespace agglo::run
