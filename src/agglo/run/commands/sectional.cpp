// agglo sectional: deterministic sectional (fixed-pivot) coagulation of an acoustic case file with a
// kernel of the sizes only; the same efficiency.csv and psd.csv as agglo acoustic (docs/sectional.md).
#include "agglo/run/checkpoint_io.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/sectional/run.hpp"
#include "agglo/writers/acoustic.hpp"

namespace agglo::run {

namespace {

class Sectional final : public Command {
 public:
  std::string_view name() const override { return "sectional"; }
  bool restartable() const override { return true; }
  std::string_view help() const override {
    return "deterministic sectional coagulation (fixed pivot) of an acoustic case with a size-only kernel";
  }

  void parse(Config& cfg) const override {
    (void)sectional::parse_sectional_case(cfg);
    cfg.check_unknown_keys();
  }

  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    const auto c = sectional::parse_sectional_case(cfg);
    acoustics::RunHooks hooks;
    hooks.progress = [&](double f, double t) { ctx.report().progress("sectional", f, t); };
    hooks.cancelled = [&] { return ctx.cancel && ctx.cancel->cancelled(); };
    auto ck = checkpoint_io(*this, cfg, out, ctx);  // --checkpoint, --resume (docs/restart.md)
    hooks.checkpoint_interval = ck.interval;
    hooks.checkpoint = ck.write;
    hooks.resume = ck.resume ? &*ck.resume : nullptr;
    const auto obs = sectional::run_sectional(c, hooks);
    writers::write_acoustic(out, obs, ctx.formats.csv);
    CommandResult r;
    r.summary = writers::acoustic_summary(obs);
    r.details = r.summary;
    r.data = std::make_shared<const io::Dataset>(writers::acoustic_dataset(obs));
    if (c.base.output.plots) r.plot_script = "plot_acoustic.py";
    return r;
  }
};

}  // namespace

const Command& sectional_command() {
  static const Sectional c;
  return c;
}

}  // namespace agglo::run
