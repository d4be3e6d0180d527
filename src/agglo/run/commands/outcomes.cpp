// agglo outcomes: DEM sphere-sphere or aggregate-aggregate impacts (impact/outcome_aggregates.hpp) over a
// grid of normal speed x both partners' sizes, tabulated as
// P_stick, P_bounce, P_break with Wilson intervals (impact/outcome_grid.hpp); results.nc is an outcome
// table of the DSMC (outcomes.dry_model = "table"). Every impact is a job of the ensemble runner
// (journal, --resume, all cores, MPI ranks).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/impact/outcome_aggregates.hpp"
#include "agglo/impact/outcome_fractal_law.hpp"
#include "agglo/impact/outcome_grid.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/run/ensemble.hpp"
#include "agglo/run/journal.hpp"
#include "agglo/run/reporter.hpp"
#include "agglo/writers/outcomes.hpp"

namespace agglo::run {

namespace {

struct OutcomesCase {
  impact::ImpactCase dem;
  impact::OutcomeGridSpec grid;
};

OutcomesCase outcomes_case(Config& cfg) {
  OutcomesCase c;
  c.dem = impact::parse_impact_case(cfg, /*one_sphere_target=*/true);
  c.grid = impact::parse_outcome_grid(cfg.root());
  if (c.grid.aggregates())
    impact::check_aggregate_pair(cfg.root(), c.dem, c.grid);
  else
    impact::check_sphere_sphere(cfg.root(), c.dem);
  return c;
}

// Journal key: the node's values (shortest round-trip digits) and the sample; the charges and the
// permittivity only on grids with those axes (the keys of other grids stay as they were).
std::string outcome_job_key(const impact::OutcomeGridSpec& g, const impact::OutcomeImpact& j) {
  std::string extra;
  if (!g.charges.empty()) extra += fmt::format(" sigma1={} sigma2={}", g.charges[j.c1], g.charges[j.c2]);
  if (!g.permittivities.empty()) extra += fmt::format(" kappa={}", g.permittivities[j.ik]);
  if (!g.primary_radii.empty()) extra += fmt::format(" a1={} a2={}", g.primary_radii[j.m1], g.primary_radii[j.m2]);
  if (g.aggregates())
    return fmt::format("v_n={} n1={} n2={}{} sample={} b={}", g.speeds[j.iv], g.partner_primaries(j.i1, j.m1),
                       g.partner_primaries(j.i2, j.m2), extra, j.sample, j.b_fraction);
  return fmt::format("v_n={} d1={} d2={}{} sample={} b={}", g.speeds[j.iv], g.diameters[j.i1], g.diameters[j.i2],
                     extra, j.sample, j.b_fraction);
}

// The charge, permittivity and primary-radius axes in the provenance ("" without them).
std::string charge_provenance(const impact::OutcomeGridSpec& g) {
  std::string r;
  if (!g.primary_radii.empty())
    r += fmt::format("; primary radii [{}] m of each partner (axes primary_radius_1, primary_radius_2), the counts "
                     "N (a_0 / a)^3 at the common volume-equivalent diameters 2 a_0 N^(1/3), a_0 = {:g} m",
                     fmt::join(g.primary_radii, ", "), g.primary_radii[0]);
  if (!g.charges.empty())
    r += fmt::format("; partner charges sigma pi d^2 for sigma in [{}] C/m^2 (d volume-equivalent), with the "
                     "case's electrostatics",
                     fmt::join(g.charges, ", "));
  if (!g.permittivities.empty()) r += fmt::format("; permittivities kappa_p [{}]", fmt::join(g.permittivities, ", "));
  return r;
}

// An aggregate impact's journal entry: the outcome, and for a break its fragment statistics.
nlohmann::json aggregate_result(const impact::ImpactCase& one, const impact::ImpactOutcome& o) {
  if (!o.contact)  // turned back before touching (charged grids): the two partners, a bounce
    return nlohmann::json{{"outcome", static_cast<int>(impact::PairOutcome::bounce)}, {"steps", o.steps}};
  const auto f = impact::classify_aggregate_pair(o.components, impact::pair_masses(one),
                                                 one.agglomerate.structure.size());
  nlohmann::json r{{"outcome", static_cast<int>(f.outcome)}, {"steps", o.steps}};
  if (f.outcome == impact::PairOutcome::brk) {
    r["fragments"] = f.fragments;
    r["largest"] = f.largest_fraction;
    r["fractions"] = f.fractions;
  }
  return r;
}

std::vector<Job> outcome_jobs(const OutcomesCase& c, const std::vector<impact::OutcomeImpact>& impacts) {
  std::vector<Job> jobs;
  for (const auto& j : impacts)
    jobs.push_back({outcome_job_key(c.grid, j), [&c, j](const JobContext& ctx) {
                      const impact::ImpactCase one = impact::outcome_case(c.dem, c.grid, j);
                      auto poll = [&ctx](double, double) { throw_if_cancelled(ctx.cancel); };
                      const impact::ImpactOutcome o =
                          impact::run_impact(one, impact::outcome_launch_speed(c.grid, j), nullptr, poll);
                      if (c.grid.aggregates()) return aggregate_result(one, o);
                      return nlohmann::json{{"outcome", static_cast<int>(impact::classify_pair(o))},
                                            {"steps", o.steps}};
                    }});
  return jobs;
}

std::string provenance(const OutcomesCase& c, std::size_t impacts) {
  if (c.grid.aggregates())
    return fmt::format("agglo outcomes: {} DEM aggregate-aggregate impacts of case '{}' ({} target, {} projectile, "
                       "primary radius {:g} m, primary counts [{}] as volume-equivalent diameters 2 a N^(1/3); "
                       "structures and projectile orientation drawn per impact, docs/outcomes.md); impact parameter "
                       "b^2 uniform up to ({:g} (r_1 + r_2))^2, seed {}, launch speed v_n / sqrt(1 - (b/(r_1 + r_2))^2){}",
                       impacts, c.dem.name, c.dem.agglomerate.shape, c.dem.projectile.shape, c.grid.primary_radius,
                       fmt::join(c.grid.primaries, ", "), c.grid.max_offset, c.grid.seed, charge_provenance(c.grid));
  return fmt::format("agglo outcomes: {} DEM sphere-sphere impacts of case '{}' (one-sphere target, "
                     "docs/outcomes.md); impact parameter b^2 uniform up to ({:g} (r_1 + r_2))^2, seed {}, "
                     "launch speed v_n / sqrt(1 - (b/(r_1 + r_2))^2){}",
                     impacts, c.dem.name, c.grid.max_offset, c.grid.seed, charge_provenance(c.grid));
}

// results.nc: the table with its provenance and, for the DSMC, the fractal law of aggregate structures
// (impact/outcome_fractal_law.hpp) and the launch gap of charged sphere tables (acoustics/outcome_table.hpp).
io::Dataset table_dataset(const OutcomesCase& c, const impact::OutcomeGridResult& table, const std::string& prov) {
  io::Dataset d = writers::outcomes_dataset(table, prov);
  namespace ac = acoustics;
  if (c.grid.aggregates()) {
    const impact::TableFractalLaw law = impact::table_fractal_law(c.dem, c.grid);
    if (law.known) {
      d.attributes[ac::kFractalDimensionAttribute] = law.fractal_dimension;
      d.attributes[ac::kFractalPrefactorAttribute] = law.fractal_prefactor;
      d.attributes[ac::kFractalLawAttribute] = law.how;
    }
  } else if (!c.grid.charges.empty()) {  // the target is the smaller sphere: gap g r_1 (outcome_grid.hpp)
    d.attributes[ac::kLaunchGapAttribute] = c.dem.projectile.gap_radii;
    d.attributes[ac::kMediumPermittivityAttribute] = c.dem.medium_permittivity;
  }
  return d;
}

class Outcomes final : public Command {
 public:
  std::string_view name() const override { return "outcomes"; }
  std::string_view help() const override {
    return "Sphere-sphere or aggregate-aggregate outcome table from DEM impacts: P_stick, P_bounce, P_break (and "
           "fragment statistics) over [outcome_grid] speeds x sizes x sizes (the DSMC's dry outcome table, "
           "docs/outcomes.md)";
  }
  bool resumable() const override { return true; }
  Estimate estimate(Config& cfg, const RunContext& ctx) const override {
    const OutcomesCase c = outcomes_case(cfg);
    return impact::outcomes_estimate(c.dem, c.grid, ctx.thread_count());
  }
  // The impact commands' CPU time per weighted particle-step (run/commands/impact_command.hpp).
  double seconds_per_step(Config&) const override { return 2e-8; }
  void parse(Config& cfg) const override {
    (void)outcomes_case(cfg);
    cfg.check_unknown_keys();
  }

  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    const OutcomesCase c = outcomes_case(cfg);
    const auto impacts = impact::outcome_impacts(c.grid);
    const auto jobs = outcome_jobs(c, impacts);
    Journal journal(out.file("journal.jsonl"), hash_hex(std::string(name()) + "\n" + cfg.resolved_toml()), ctx.resume);
    const auto done = run_jobs(jobs, {ctx.threads, &journal, ctx.cancel, &ctx.report(), "outcomes"});
    rethrow_first_error(done, &jobs);
    std::vector<impact::PairOutcome> outcomes;
    std::vector<double> fragments, largest;  // per impact; read for the breaks
    std::vector<std::vector<double>> fractions;  // each break's fragment mass fractions (empty: none journaled)
    long long steps = 0;
    for (const auto& o : done) {
      outcomes.push_back(static_cast<impact::PairOutcome>(o.result.at("outcome").get<int>()));
      steps += o.result.at("steps").get<long long>();
      fragments.push_back(o.result.value("fragments", 0.0));
      largest.push_back(o.result.value("largest", 0.0));
      fractions.push_back(o.result.value("fractions", std::vector<double>{}));
    }
    const auto table = impact::tabulate_outcomes(c.grid, outcomes, fragments, largest, fractions);
    if (ctx.formats.csv) writers::write_outcomes(out, table);
    CommandResult r;
    r.data = std::make_shared<const io::Dataset>(table_dataset(c, table, provenance(c, impacts.size())));
    std::int64_t sticks = 0, breaks = 0;
    for (const auto& o : outcomes) {
      sticks += o == impact::PairOutcome::stick;
      breaks += o == impact::PairOutcome::brk;
    }
    r.summary = {{"impacts", impacts.size()}, {"stuck", sticks}, {"dem_steps", steps},
                 {"nodes", table.impacts.size()}};
    r.seed = static_cast<long long>(c.grid.seed);
    const auto n = static_cast<std::int64_t>(impacts.size());
    if (c.grid.aggregates())
      ctx.report().info(fmt::format("{}: {} impacts over {} speeds x {} x {} primary counts: {} stuck, {} bounced, {} broke",
                                    c.dem.name, n, c.grid.speeds.size(), c.grid.sizes(), c.grid.sizes(), sticks,
                                    n - sticks - breaks, breaks));
    else
      ctx.report().info(fmt::format("{}: {} impacts over {} speeds x {} x {} diameters: {} stuck, {} bounced", c.dem.name,
                                    n, c.grid.speeds.size(), c.grid.diameters.size(), c.grid.diameters.size(), sticks,
                                    n - sticks));
    return r;
  }
};

}  // namespace

const Command& outcomes_command() {
  static const Outcomes c;
  return c;
}

}  // namespace agglo::run
