// agglo breakup: break-up probability vs speed over an ensemble of impact offsets.
#include <fmt/format.h>

#include "agglo/impact/estimate.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/run/commands/impact_command.hpp"
#include "agglo/run/impact_ensemble.hpp"
#include "agglo/writers/impact.hpp"

namespace agglo::run {

namespace {

nlohmann::json level(double v) { return v < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(v); }
std::string level_text(double v) { return v < 0.0 ? std::string("not reached") : fmt::format("{:.4f} m/s", v); }

class Breakup final : public ImpactCommand {
 public:
  std::string_view name() const override { return "breakup"; }
  std::string_view help() const override {
    return "Break-up probability vs speed over an ensemble of impact offsets and agglomerate orientations "
           "([breakup] speeds, samples, offset_spread, orientations)";
  }

  bool resumable() const override { return true; }

  Estimate estimate(Config& cfg, const RunContext& ctx) const override {
    return impact::breakup_estimate(impact_case(cfg), ctx.thread_count());
  }

  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    const auto c = impact_case(cfg);
    const auto relaxed = relaxed_target(c, ctx);  // independent of the projectile offset
    Journal journal(out.file("journal.jsonl"), impact_context(name(), cfg), ctx.resume);
    const EnsembleOptions opt{ctx.threads, &journal, ctx.cancel, &ctx.report(), "breakup"};
    const auto res = impact::breakup_probability(c.breakup, c.projectile.offset_radii, impact_batch(c, relaxed, opt));
    if (ctx.formats.csv) writers::write_breakup(out, res);
    CommandResult r;
    r.data = std::make_shared<const io::Dataset>(writers::breakup_dataset(res));
    r.summary = {{"v10", level(res.v10)}, {"v50", level(res.v50)}, {"v90", level(res.v90)},
                 {"runs", res.outcomes.size()}};
    r.plot_script = "plot_breakup.py";
    const std::string rotations = res.orientations > 1 ? fmt::format(" x {} orientations", res.orientations) : "";
    ctx.report().info(fmt::format("{}: break-up probability at {} speeds x {} offsets{}: v10 = {}, v50 = {}, v90 = {}",
                                  c.name, res.points.size(), res.offsets.size(), rotations, level_text(res.v10),
                                  level_text(res.v50), level_text(res.v90)));
    return r;
  }
};

}  // namespace

const Command& breakup_command() {
  static const Breakup c;
  return c;
}

}  // namespace agglo::run
