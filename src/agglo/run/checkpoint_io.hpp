#pragma once
// Checkpoints of a restartable command in its output folder (docs/restart.md): a writer of
// out/checkpoint.bin under the command's name and the hash of its resolved config (every --checkpoint
// interval; without --checkpoint only where an interrupted run stops), and under --resume the reader of
// the folder's checkpoint when it has one (ConfigError when it belongs to another command, config,
// build or format; a warning that the run starts again when the folder has none).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "agglo/core/config.hpp"
#include "agglo/io/checkpoint.hpp"
#include "agglo/run/command.hpp"

namespace agglo::run {

struct CheckpointIO {
  // Writes the payload of the state at (step, simulated time [s]); without --checkpoint it writes only
  // once the run is cancelled (the forced write where it stops).
  std::function<void(std::uint64_t step, double t, const std::string& payload)> write;
  double interval = 0.0;                        // [s] (--checkpoint; infinity without)
  bool periodic = false;                        // --checkpoint given: the state at the end is written too
  std::optional<io::CheckpointReader> resume;   // the payload to continue from; empty: from the start
};

CheckpointIO checkpoint_io(const Command& cmd, const Config& cfg, const OutputDir& out, const RunContext& ctx);

}  // namespace agglo::run
