#pragma once
// Checkpoints of `agglo collide` (docs/restart.md, "Collide"): with --checkpoint INTERVAL a checkpoint of the
// whole collision state (impact/checkpoint.hpp) is written each time the simulated time since
// launch crosses a multiple of INTERVAL, when the run is interrupted (at the step boundary where the
// cancellation is seen; also without --checkpoint) and at the end. Under --resume the run continues from the folder's checkpoint
// (none: from the launch); a checkpoint of another build or config is refused (ConfigError).
#include <optional>

#include "agglo/core/config.hpp"
#include "agglo/impact/impact_run.hpp"
#include "agglo/run/checkpoint_io.hpp"
#include "agglo/run/command.hpp"

namespace agglo::run {

class CollideCheckpoints {
 public:
  // The folder's checkpoint is read here under --resume (run/checkpoint_io.hpp, shared with acoustic and
  // sectional); ConfigError when it belongs to another command, config, build or format.
  CollideCheckpoints(const Command& collide, const Config& cfg, const OutputDir& out, const RunContext& ctx);
  // The state to continue from under --resume when the folder has a checkpoint.
  std::optional<impact::ImpactState> resume_state();
  // Called at every step boundary: checkpoint when due; on cancellation checkpoint (with or without
  // an interval) and throw InterruptedError.
  void at_boundary(const impact::ImpactRun& run);
  // The checkpoint of the final state (with an interval).
  void at_end(const impact::ImpactRun& run);

 private:
  void save(const impact::ImpactRun& run);
  const RunContext& ctx_;
  CheckpointIO io_;
  long long last_multiple_ = -1;  // of the interval, reached at the last boundary
};

}  // namespace agglo::run
