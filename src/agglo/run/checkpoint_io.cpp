#include "agglo/run/checkpoint_io.hpp"

namespace agglo::run {

CheckpointIO checkpoint_io(const Command& cmd, const Config& cfg, const OutputDir& out, const RunContext& ctx) {
  CheckpointIO res;
  const io::CheckpointHeader header{std::string(cmd.name()), io::config_hash(cfg.resolved_toml())};
  if (ctx.checkpoint_interval > 0.0) {
    res.interval = ctx.checkpoint_interval;
    res.write = [header, &out](std::uint64_t step, double t, const std::string& payload) {
      io::write_checkpoint(out, {header.command, header.config_hash, step, t}, payload);
    };
  }
  io::CheckpointHeader found;
  if (ctx.resume && io::has_checkpoint(out)) res.resume.emplace(io::read_checkpoint(out, header, found));
  return res;
}

}  // namespace agglo::run
