// agglo acoustic: DSMC acoustic agglomeration of fine particles with droplets (docs/model.md Part C).
#include <optional>

#include "agglo/acoustics/estimate.hpp"
#include "agglo/acoustics/run.hpp"
#include "agglo/core/error.hpp"
#include "agglo/io/acoustic_dataset.hpp"
#include "agglo/io/acoustic_writers.hpp"
#include "agglo/io/checkpoint.hpp"
#include "agglo/run/commands.hpp"

namespace agglo::run {

namespace {

class Acoustic final : public Command {
 public:
  std::string_view name() const override { return "acoustic"; }
  bool restartable() const override { return true; }
  std::string_view help() const override {
    return "DSMC acoustic agglomeration of fine particles with droplets (seed 002)";
  }

  void parse(Config& cfg) const override {
    (void)acoustics::parse_acoustic_case(cfg);
    cfg.check_unknown_keys();
  }

  Estimate estimate(Config& cfg, const RunContext&) const override {
    return acoustics::acoustic_estimate(acoustics::parse_acoustic_case(cfg));
  }

  long long seed(const Config& cfg) const override {
    Config probe = cfg.clone();
    return static_cast<long long>(acoustics::parse_acoustic_case(probe).engine.seed);
  }

  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    const auto c = acoustics::parse_acoustic_case(cfg);
    acoustics::RunHooks hooks;
    hooks.progress = [&](double f, double t) { ctx.report().progress("acoustic", f, t); };
    hooks.warning = [&](const std::string& w) { ctx.report().warning(w); };
    hooks.cancelled = [&] { return ctx.cancel && ctx.cancel->cancelled(); };
    // Checkpoints (--checkpoint) and the exact restart from the folder's last one (--resume).
    const io::CheckpointHeader header{std::string(name()), io::config_hash(cfg.resolved_toml())};
    hooks.checkpoint_interval = ctx.checkpoint_interval;
    hooks.checkpoint = [&](std::uint64_t step, double t, const std::string& payload) {
      io::write_checkpoint(out, {header.command, header.config_hash, step, t}, payload);
    };
    std::optional<io::CheckpointReader> resume;
    io::CheckpointHeader found;
    if (ctx.resume && io::has_checkpoint(out)) resume.emplace(io::read_checkpoint(out, header, found));
    hooks.resume = resume ? &*resume : nullptr;
    const auto obs = acoustics::run_acoustic(c, hooks);
    io::write_acoustic(out, obs, ctx.formats.csv);
    if (!obs.interrupted.empty()) throw InterruptedError(obs.interrupted);  // partial results flushed
    CommandResult r;
    r.summary = io::acoustic_summary(obs);
    r.details = r.summary;
    r.seed = static_cast<long long>(c.engine.seed);
    r.data = std::make_shared<const io::Dataset>(io::acoustic_dataset(obs));
    if (c.output.plots) r.plot_script = "plot_acoustic.py";
    return r;
  }
};

}  // namespace

const Command& acoustic_command() {
  static const Acoustic c;
  return c;
}

}  // namespace agglo::run
