#include "agglo/run/checkpoint_io.hpp"

#include <limits>

#include <fmt/format.h>

#include "agglo/run/budget.hpp"

namespace agglo::run {

CheckpointIO checkpoint_io(const Command& cmd, const Config& cfg, const OutputDir& out, const RunContext& ctx) {
  CheckpointIO res;
  const io::CheckpointHeader header{std::string(cmd.name()), io::config_hash(cfg.resolved_toml())};
  // Without --checkpoint the state is still saved when the run is interrupted, so that --resume continues
  // it (docs/restart.md): the engines' schedules see an infinite interval (a write only where the run
  // stops), and the forced write at the end of a run that was not cancelled is skipped.
  const bool periodic = ctx.checkpoint_interval > 0.0;
  res.interval = periodic ? ctx.checkpoint_interval : std::numeric_limits<double>::infinity();
  res.periodic = periodic;
  const CancelToken* cancel = ctx.cancel;
  res.write = [header, &out, periodic, cancel](std::uint64_t step, double t, const std::string& payload) {
    if (!periodic && !(cancel && cancel->cancelled())) return;
    io::write_checkpoint(out, {header.command, header.config_hash, step, t}, payload);
  };
  if (!ctx.resume) return res;
  io::CheckpointHeader found;
  if (io::has_checkpoint(out)) {
    res.resume.emplace(io::read_checkpoint(out, header, found, budgets_of(ctx).max_memory_bytes));
  } else {
    ctx.report().warning(fmt::format(
        "--resume: {} has no {} (the run was killed, or stopped before it started stepping): {} starts again from "
        "the beginning; the files of the earlier run stay until this run replaces them",
        out.path().string(), io::kCheckpointFile, cmd.name()));
  }
  return res;
}

}  // namespace agglo::run
