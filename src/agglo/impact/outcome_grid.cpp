#include "agglo/impact/outcome_grid.hpp"

#include <cmath>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/core/rng.hpp"
#include "agglo/core/settings_outcomes.hpp"
#include "agglo/impact/estimate.hpp"
#include "agglo/impact/outcome_aggregates.hpp"
#include "agglo/impact/vcrit.hpp"

namespace agglo::impact {

namespace {

constexpr double kMaxGridImpacts = 1e6;
constexpr std::uint64_t kOffsetStream = 0x6f7574636f6d65ULL;  // "outcome": the impact parameters' stream

void check_increasing(const settings::Reals& key, const ConfigSection& s, const std::vector<double>& a) {
  if (a.empty()) key.reject(s, "needs at least one value");
  for (std::size_t k = 1; k < a.size(); ++k)
    if (!(a[k] > a[k - 1]))
      key.reject(s, fmt::format("must be strictly increasing (value {} = {:g} after {:g})", k, a[k], a[k - 1]));
}

}  // namespace

OutcomeGridSpec parse_outcome_grid(const ConfigSection& root) {
  const auto& k = settings::outcomes_settings().grid;
  ConfigSection s = k.t.open(root);
  OutcomeGridSpec g;
  g.speeds = k.speeds.read(s);
  check_increasing(k.speeds, s, g.speeds);
  if (k.primaries.present(s)) {  // aggregate partners: the diameters follow from the case (outcome_aggregates.hpp)
    if (k.diameters.present(s)) k.diameters.reject(s, fmt::format("give {} or {}, not both", k.diameters.dotted(),
                                                                  k.primaries.dotted()));
    const std::vector<double> n = k.primaries.read(s);
    check_increasing(k.primaries, s, n);
    for (double x : n) {
      if (x != std::floor(x)) k.primaries.reject(s, fmt::format("{:g} is not a whole number", x));
      g.primaries.push_back(static_cast<int>(x));
    }
  } else {
    g.diameters = k.diameters.read(s);
    check_increasing(k.diameters, s, g.diameters);
  }
  g.impacts = static_cast<int>(k.impacts.read(s));
  g.max_offset = k.max_offset.read(s);
  g.seed = static_cast<std::uint64_t>(k.seed.read(s));
  const double nd = static_cast<double>(g.sizes());
  const double total = static_cast<double>(g.speeds.size()) * nd * (nd + 1.0) / 2.0 * g.impacts;
  if (total > kMaxGridImpacts)
    k.impacts.reject(s, fmt::format("gives {:.0f} impacts over the grid, more than the limit of {:.0f}", total,
                                    kMaxGridImpacts));
  return g;
}

void check_sphere_sphere(const ConfigSection& root, const ImpactCase& c) {
  const auto& k = impact_keys();
  const ConfigSection ag = k.agglomerate.t.open(root);
  if (c.agglomerate.shape != "list" || c.agglomerate.particles.size() != 1)
    k.agglomerate.shape.reject(ag, fmt::format("agglo outcomes needs a one-sphere target: shape = \"list\" with one "
                                               "[[particles]] entry (its radius is set by {})",
                                               settings::outcomes_settings().grid.diameters.dotted()));
  if (c.projectile.shape != "sphere")
    k.projectile.shape.reject(k.projectile.t.open(root), "agglo outcomes tabulates sphere-sphere impacts: use \"sphere\"");
  if (c.dem.dt > 0.0)  // one step for every size would be too long for the smallest pairs or wasteful for the largest
    k.time.dt.reject(k.time.t.open(root), fmt::format("agglo outcomes takes each node's step from its contact period: "
                                                      "set 0 and choose {}",
                                                      k.time.steps_per_period.dotted()));
  if (!c.dem.walls.empty())
    k.wall.t.fail(root, "agglo outcomes tabulates sphere-sphere impacts: remove the [wall] table");
}

std::vector<OutcomeImpact> outcome_impacts(const OutcomeGridSpec& s) {
  std::vector<OutcomeImpact> out;
  const std::size_t nd = s.sizes();
  for (std::size_t iv = 0; iv < s.speeds.size(); ++iv)
    for (std::size_t i1 = 0; i1 < nd; ++i1)
      for (std::size_t i2 = i1; i2 < nd; ++i2) {
        const std::uint64_t node = (iv * nd + i1) * nd + i2;
        CounterRng rng(s.seed, kOffsetStream, node);
        for (int k = 0; k < s.impacts; ++k)
          out.push_back({iv, i1, i2, k, s.max_offset * std::sqrt(rng.uniform())});
      }
  return out;
}

ImpactCase outcome_case(const ImpactCase& base, const OutcomeGridSpec& s, const OutcomeImpact& j) {
  if (s.aggregates()) return aggregate_outcome_case(base, s, j);
  ImpactCase c = base;
  const double r1 = 0.5 * s.diameters[j.i1], r2 = 0.5 * s.diameters[j.i2];
  c.agglomerate.particles.at(0).radius = r1;
  c.agglomerate.radius = r1;  // the length unit r_p of the gap and the offset
  c.projectile.radius = r2;
  c.projectile.offset_radii = j.b_fraction * (r1 + r2) / r1;
  return c;
}

double outcome_launch_speed(const OutcomeGridSpec& s, const OutcomeImpact& j) {
  return s.speeds[j.iv] / std::sqrt(1.0 - j.b_fraction * j.b_fraction);
}

Estimate outcomes_estimate(const ImpactCase& base, const OutcomeGridSpec& s, int threads) {
  constexpr double kNodeBytes = 400.0, kJournalLineBytes = 250.0;  // a CSV row + 16 values; one journal line
  const auto& g = settings::outcomes_settings().grid;
  const std::vector<std::string> keys = {std::string(g.speeds.dotted()),
                                         std::string(s.aggregates() ? g.primaries.dotted() : g.diameters.dotted()),
                                         std::string(g.impacts.dotted())};
  Estimate e;
  const std::size_t nd = s.sizes();
  double memory = 0.0;
  for (std::size_t i1 = 0; i1 < nd; ++i1)
    for (std::size_t i2 = i1; i2 < nd; ++i2)
      for (std::size_t iv = 0; iv < s.speeds.size(); ++iv) {
        const OutcomeImpact worst{iv, i1, i2, 0, s.max_offset};  // fastest launch, widest approach
        const ImpactCase c = outcome_case(base, s, worst);
        const double particles = s.aggregates() ? s.primaries[i1] + s.primaries[i2] : 2.0;
        add_to(e.steps, particles * run_steps_bound(c, outcome_launch_speed(s, worst)) * s.impacts, keys);
        if (iv == 0) memory = std::max(memory, collide_estimate(c).memory.value);
      }
  add_to(e.steps, 0.0, {std::string(impact_keys().time.after_contact.dotted())});
  add_to(e.memory, std::max(1, threads) * memory, keys);
  const double nodes = static_cast<double>(s.speeds.size() * nd * nd);
  const double impacts = static_cast<double>(s.speeds.size()) * static_cast<double>(nd * (nd + 1) / 2) * s.impacts;
  add_to(e.output, nodes * kNodeBytes + impacts * kJournalLineBytes, keys);
  return e;
}

PairOutcome classify_pair(const ImpactOutcome& o) {
  if (o.broken) return PairOutcome::brk;
  return stays(o) ? PairOutcome::stick : PairOutcome::bounce;
}

WilsonInterval wilson_interval(std::int64_t k, std::int64_t n) {
  if (n <= 0) return {};
  constexpr double z = 1.959963984540054;
  const double nn = static_cast<double>(n), p = static_cast<double>(k) / nn, z2 = z * z;
  const double centre = p + z2 / (2.0 * nn), half = z * std::sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn));
  // At k = 0 (k = n) the lower (upper) end is exactly 0 (1); computed, it would carry a rounding error.
  return {k == 0 ? 0.0 : (centre - half) / (1.0 + z2 / nn), k == n ? 1.0 : (centre + half) / (1.0 + z2 / nn)};
}

OutcomeGridResult tabulate_outcomes(const OutcomeGridSpec& spec, const std::vector<PairOutcome>& outcomes,
                                    const std::vector<double>& fragments, const std::vector<double>& largest) {
  OutcomeGridResult r;
  r.spec = spec;
  const std::size_t n = spec.speeds.size() * spec.sizes() * spec.sizes();
  r.sticks.assign(n, 0);
  r.bounces.assign(n, 0);
  r.breaks.assign(n, 0);
  r.impacts.assign(n, 0);
  if (spec.aggregates()) {
    r.fragments.assign(n, 0.0);
    r.largest_fraction.assign(n, 0.0);
  }
  const auto jobs = outcome_impacts(spec);
  for (std::size_t k = 0; k < jobs.size() && k < outcomes.size(); ++k) {
    const OutcomeImpact& j = jobs[k];
    const std::size_t mirror = j.i1 == j.i2 ? 1 : 2;
    for (std::size_t m = 0; m < mirror; ++m) {
      const std::size_t i = m == 0 ? r.index(j.iv, j.i1, j.i2) : r.index(j.iv, j.i2, j.i1);
      ++r.impacts[i];
      ++(outcomes[k] == PairOutcome::stick ? r.sticks : outcomes[k] == PairOutcome::bounce ? r.bounces : r.breaks)[i];
      if (spec.aggregates() && outcomes[k] == PairOutcome::brk) {
        r.fragments[i] += fragments.at(k);
        r.largest_fraction[i] += largest.at(k);
      }
    }
  }
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {  // sums over the breaks -> their means
    const double nb = static_cast<double>(r.breaks[i]);
    r.fragments[i] = r.breaks[i] > 0 ? r.fragments[i] / nb : std::nan("");
    r.largest_fraction[i] = r.breaks[i] > 0 ? r.largest_fraction[i] / nb : std::nan("");
    // mean f_L >= 1/mean N_f holds exactly (Jensen); with equal fragments it can miss by a rounding error
    const double floor_fl = 1.0 / r.fragments[i];
    if (r.largest_fraction[i] < floor_fl && r.largest_fraction[i] > floor_fl * (1.0 - 1e-12))
      r.largest_fraction[i] = floor_fl;
  }
  return r;
}

}  // namespace agglo::impact
