// agglo acoustic: DSMC acoustic agglomeration of fine particles with droplets (docs/model.md Part C).
#include <fmt/format.h>

#include "agglo/acoustics/estimate.hpp"
#include "agglo/acoustics/run.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/settings_acoustic.hpp"
#include "agglo/run/checkpoint_io.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/writers/acoustic.hpp"

namespace agglo::run {

namespace {

class Acoustic final : public Command {
 public:
  std::string_view name() const override { return "acoustic"; }
  bool restartable() const override { return true; }
  std::string_view help() const override {
    return "DSMC acoustic agglomeration of fine particles with droplets (Zhao et al. 2023)";
  }

  void parse(Config& cfg) const override {
    (void)acoustics::parse_acoustic_case(cfg);
    cfg.check_unknown_keys();
  }

  // 6e-8 s per sample-step: the seed-002 baseline with time.end = 0.2 s on one thread, 4.67 s of CPU
  // for 7.87e7 estimated sample-steps (the estimate is the engine's exact count).
  double seconds_per_step(Config&) const override { return 6e-8; }

  Estimate estimate(Config& cfg, const RunContext&) const override {
    return acoustics::acoustic_estimate(acoustics::parse_acoustic_case(cfg));
  }

  const settings::Setting* seed_key() const override { return &settings::acoustic_settings().top.seed; }

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
    auto ck = checkpoint_io(*this, cfg, out, ctx);  // --checkpoint, --resume (docs/restart.md)
    hooks.checkpoint_interval = ck.interval;
    hooks.checkpoint = ck.write;
    hooks.checkpoint_at_end = ck.periodic;
    hooks.resume = ck.resume ? &*ck.resume : nullptr;
    const auto obs = acoustics::run_acoustic(c, hooks);
    writers::write_acoustic(out, obs, ctx.formats.csv);
    if (!obs.interrupted.empty()) {  // partial results flushed (results.nc with status "incomplete")
      if (ctx.formats.netcdf)
        write_results_nc(out, cfg, name(), static_cast<long long>(c.engine.seed), writers::acoustic_dataset(obs),
                         "incomplete");
      throw InterruptedError(obs.interrupted);
    }
    CommandResult r;
    r.summary = writers::acoustic_summary(obs);
    r.details = r.summary;
    r.seed = static_cast<long long>(c.engine.seed);
    r.data = std::make_shared<const io::Dataset>(writers::acoustic_dataset(obs));
    if (c.output.plots) r.plot_script = "plot_acoustic.py";
    const auto& last = obs.efficiency.back();
    ctx.report().info(fmt::format("{}: t = {:.6g} s, {} samples -> fine-particle removal efficiency {:.4g}, "
                                  "pure-droplet fraction {:.4g}; outputs in {}",
                                  std::filesystem::path(cfg.file()).stem().string(), last.t, obs.samples,
                                  last.fine_efficiency, last.pure_droplet_fraction, out.path().string()));
    return r;
  }
};

}  // namespace

const Command& acoustic_command() {
  static const Acoustic c;
  return c;
}

}  // namespace agglo::run
