// agglo vcrit: critical break-up velocity by a scan and bisection rounds of impacts.
#include <fmt/format.h>

#include "agglo/core/settings_impact.hpp"
#include "agglo/impact/estimate.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/run/commands/impact_command.hpp"
#include "agglo/run/impact_ensemble.hpp"
#include "agglo/run/ranks.hpp"
#include "agglo/writers/impact.hpp"

namespace agglo::run {

namespace {

// Under mpirun: the bisection rounds after the scan have points_per_round jobs, so job slots beyond that
// wait (docs/scaling.md, "Cost model").
void warn_idle_slots(int points_per_round, const RunContext& ctx) {
  const int slots = rank_count() * resolve_threads(ctx.threads);
  const std::string key(settings::impact_settings().vcrit.points_per_round.dotted());
  if (rank_count() > 1 && slots > points_per_round)
    ctx.report().warning(fmt::format("vcrit: each bisection round runs {} = {} speeds, so {} of the {} job slots "
                                     "({} ranks x {} threads) wait during the bisection; raise {} to use them",
                                     key, points_per_round, slots - points_per_round, slots, rank_count(),
                                     resolve_threads(ctx.threads), key));
}

class Vcrit final : public ImpactCommand {
 public:
  std::string_view name() const override { return "vcrit"; }
  std::string_view help() const override { return "Critical break-up velocity of an agglomerate (bisection on speed)"; }

  bool resumable() const override { return true; }

  Estimate estimate(Config& cfg, const RunContext& ctx) const override {
    return impact::vcrit_estimate(impact_case(cfg), ctx.thread_count());
  }

  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    const auto c = impact_case(cfg);
    warn_idle_slots(c.vcrit.points_per_round, ctx);
    const auto relaxed = relaxed_target(c, ctx);  // one relaxation for every speed
    Journal journal(out.file("journal.jsonl"), impact_context(name(), cfg), ctx.resume);
    const EnsembleOptions opt{ctx.threads, &journal, ctx.cancel, nullptr, "vcrit"};
    const auto res = impact::find_vcrit(c.vcrit, speed_batch(c, relaxed, opt),
                                        [&](double f) { ctx.report().progress("vcrit", f, 0.0); });
    if (ctx.formats.csv) out.write_json("vcrit.json", writers::vcrit_json(res));
    CommandResult r;
    r.data = std::make_shared<const io::Dataset>(writers::vcrit_dataset(res));
    r.summary = {{"v_crit", res.v_crit}, {"bracket_lo", res.lo}, {"bracket_hi", res.hi}, {"rounds", res.rounds},
                 {"runs", res.runs.size()}, {"warnings", res.warnings.size()}};
    r.plot_script = "plot_vcrit.py";
    ctx.report().info(fmt::format("{}: v_crit = {:.4f} m/s{} (bracket [{:.5f}, {:.5f}], {} runs)", c.name, res.v_crit,
                                  res.sticking ? " (sticking)" : "", res.lo, res.hi, res.runs.size()));
    for (const auto& w : res.warnings) ctx.report().warning(w);
    return r;
  }
};

}  // namespace

const Command& vcrit_command() {
  static const Vcrit c;
  return c;
}

}  // namespace agglo::run
