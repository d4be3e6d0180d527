#include "agglo/impact/outcome_grid.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "agglo/core/constants.hpp"
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
  if (k.charges.present(s)) {
    g.charges = k.charges.read(s);
    check_increasing(k.charges, s, g.charges);
  }
  if (k.permittivities.present(s)) {
    g.permittivities = k.permittivities.read(s);
    check_increasing(k.permittivities, s, g.permittivities);
  }
  if (k.primary_radii.present(s)) {  // whole primary counts at every radius: outcome_aggregates.cpp
    if (!g.aggregates())
      k.primary_radii.reject(s, fmt::format("needs aggregate partners ({}); sphere tables have no primary radii",
                                            k.primaries.dotted()));
    g.primary_radii = k.primary_radii.read(s);
    check_increasing(k.primary_radii, s, g.primary_radii);
  }
  g.impacts = static_cast<int>(k.impacts.read(s));
  g.max_offset = k.max_offset.read(s);
  g.seed = static_cast<std::uint64_t>(k.seed.read(s));
  const double total = static_cast<double>(outcome_impacts_count(g));
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

int OutcomeGridSpec::partner_primaries(std::size_t i, std::size_t m) const {
  if (primary_radii.empty() || m == 0) return primaries[i];
  const double ratio = primary_radii[0] / primary_radii[m];
  return static_cast<int>(std::lround(primaries[i] * ratio * ratio * ratio));
}

std::size_t outcome_impacts_count(const OutcomeGridSpec& s) {
  const std::size_t nd = s.sizes(), np = s.charge_nodes() * s.radius_nodes();
  // a partner is (size, charge, radius): size pairs i1 < i2 take every pair of (charge, radius), i1 = i2
  // those with (c1, m1) <= (c2, m2)
  const std::size_t pairs = nd * (nd - 1) / 2 * np * np + nd * np * (np + 1) / 2;
  return s.speeds.size() * pairs * s.permittivity_nodes() * static_cast<std::size_t>(s.impacts);
}

namespace {

// Node (i1, i2, c1, c2, m1, m2) is tabulated by its own runs (else it copies its mirror).
bool canonical_node(std::size_t i1, std::size_t i2, std::size_t c1, std::size_t c2, std::size_t m1, std::size_t m2) {
  return i1 < i2 || (i1 == i2 && (c1 < c2 || (c1 == c2 && m1 <= m2)));
}

}  // namespace

std::vector<OutcomeImpact> outcome_impacts(const OutcomeGridSpec& s) {
  std::vector<OutcomeImpact> out;
  const std::size_t nd = s.sizes(), nc = s.charge_nodes(), nk = s.permittivity_nodes(), nm = s.radius_nodes();
  for (std::size_t iv = 0; iv < s.speeds.size(); ++iv)
    for (std::size_t i1 = 0; i1 < nd; ++i1)
      for (std::size_t i2 = i1; i2 < nd; ++i2)
        for (std::size_t c1 = 0; c1 < nc; ++c1)
          for (std::size_t c2 = i1 == i2 ? c1 : 0; c2 < nc; ++c2)
            for (std::size_t ik = 0; ik < nk; ++ik)
              for (std::size_t m1 = 0; m1 < nm; ++m1)
                for (std::size_t m2 = 0; m2 < nm; ++m2) {
                  if (!canonical_node(i1, i2, c1, c2, m1, m2)) continue;
                  // keyed by (speed, sizes) alone: every charge, permittivity and radius sees the same offsets
                  CounterRng rng(s.seed, kOffsetStream, (iv * nd + i1) * nd + i2);
                  for (int k = 0; k < s.impacts; ++k)
                    out.push_back({iv, i1, i2, k, s.max_offset * std::sqrt(rng.uniform()), c1, c2, ik, m1, m2});
                }
  return out;
}

namespace {

// The partners' charges sigma pi d^2 and permittivity of impact j (outcome_grid.hpp), when the grid has those axes.
void set_outcome_charges(const OutcomeGridSpec& s, const OutcomeImpact& j, ImpactCase& c) {
  const double d1 = s.diameters[j.i1], d2 = s.diameters[j.i2];
  const double q1 = s.charges.empty() ? 0.0 : s.charges[j.c1] * constants::pi * d1 * d1;
  const double q2 = s.charges.empty() ? 0.0 : s.charges[j.c2] * constants::pi * d2 * d2;
  const bool charges = !s.charges.empty(), kappa = !s.permittivities.empty();
  const double k = kappa ? s.permittivities[j.ik] : 1.0;
  if (s.aggregates()) {  // Q spread evenly over the primaries of each partner
    for (auto* a : {&c.agglomerate, &c.projectile.body}) {
      const double n = static_cast<double>(a->structure.size());
      if (charges) a->structure.charge.assign(a->structure.size(), (a == &c.agglomerate ? q1 : q2) / n);
      if (kappa) a->structure.permittivity.assign(a->structure.size(), k);
    }
  } else {
    auto& target = c.agglomerate.particles.at(0);
    if (charges) target.charge = q1, c.projectile.charge = q2;
    if (kappa) target.permittivity = k, c.projectile.permittivity = k;
  }
  if (charges) {
    c.electrostatics = c.electrostatics || q1 != 0.0 || q2 != 0.0;
    c.miss_is_outcome = true;  // like charges may turn the projectile back: a bounce (never touched)
  }
}

}  // namespace

ImpactCase outcome_case(const ImpactCase& base, const OutcomeGridSpec& s, const OutcomeImpact& j) {
  if (s.aggregates()) {
    ImpactCase c = aggregate_outcome_case(base, s, j);
    set_outcome_charges(s, j, c);
    return c;
  }
  ImpactCase c = base;
  const double r1 = 0.5 * s.diameters[j.i1], r2 = 0.5 * s.diameters[j.i2];
  c.agglomerate.particles.at(0).radius = r1;
  c.agglomerate.radius = r1;  // the length unit r_p of the gap and the offset
  c.projectile.radius = r2;
  c.projectile.offset_radii = j.b_fraction * (r1 + r2) / r1;
  set_outcome_charges(s, j, c);
  return c;
}

double outcome_launch_speed(const OutcomeGridSpec& s, const OutcomeImpact& j) {
  return s.speeds[j.iv] / std::sqrt(1.0 - j.b_fraction * j.b_fraction);
}

Estimate outcomes_estimate(const ImpactCase& base, const OutcomeGridSpec& s, int threads) {
  constexpr double kNodeBytes = 400.0, kJournalLineBytes = 250.0;  // a CSV row + 16 values; one journal line
  const auto& g = settings::outcomes_settings().grid;
  std::vector<std::string> keys = {std::string(g.speeds.dotted()),
                                   std::string(s.aggregates() ? g.primaries.dotted() : g.diameters.dotted()),
                                   std::string(g.impacts.dotted())};
  if (!s.charges.empty()) keys.emplace_back(g.charges.dotted());
  if (!s.permittivities.empty()) keys.emplace_back(g.permittivities.dotted());
  if (!s.primary_radii.empty()) keys.emplace_back(g.primary_radii.dotted());
  Estimate e;
  const std::size_t nd = s.sizes(), nc = s.charge_nodes(), nm = s.radius_nodes();
  double memory = 0.0;
  for (std::size_t i1 = 0; i1 < nd; ++i1)
    for (std::size_t i2 = i1; i2 < nd; ++i2)
      for (std::size_t m1 = 0; m1 < nm; ++m1)
        for (std::size_t m2 = i1 == i2 ? m1 : 0; m2 < nm; ++m2)
          for (std::size_t iv = 0; iv < s.speeds.size(); ++iv) {
            const OutcomeImpact worst{iv, i1, i2, 0, s.max_offset, 0, 0, 0, m1, m2};  // fastest launch, widest approach
            const ImpactCase c = outcome_case(base, s, worst);
            const double particles =
                s.aggregates() ? s.partner_primaries(i1, m1) + s.partner_primaries(i2, m2) : 2.0;
            // the charge and permittivity nodes of this pair of partners (outcome_impacts)
            const bool same = i1 == i2 && m1 == m2;
            const double copies = static_cast<double>((same ? nc * (nc + 1) / 2 : nc * nc) * s.permittivity_nodes());
            add_to(e.steps, particles * run_steps_bound(c, outcome_launch_speed(s, worst)) * s.impacts * copies, keys);
            if (iv == 0) memory = std::max(memory, collide_estimate(c).memory.value);
          }
  add_to(e.steps, 0.0, {std::string(impact_keys().time.after_contact.dotted())});
  add_to(e.memory, std::max(1, threads) * memory, keys);
  const double nodes = static_cast<double>(s.nodes());
  const double impacts = static_cast<double>(outcome_impacts_count(s));
  add_to(e.output, nodes * kNodeBytes + impacts * kJournalLineBytes, keys);
  return e;
}

PairOutcome classify_pair(const ImpactOutcome& o) {
  if (o.broken) return PairOutcome::brk;
  // a separated charged pair that is bound (pair_energy < 0) comes back and cannot escape: a stick
  return stays(o) || (o.contact && o.pair_energy < 0.0) ? PairOutcome::stick : PairOutcome::bounce;
}

WilsonInterval wilson_interval(std::int64_t k, std::int64_t n) {
  if (n <= 0) return {};
  constexpr double z = 1.959963984540054;
  const double nn = static_cast<double>(n), p = static_cast<double>(k) / nn, z2 = z * z;
  const double centre = p + z2 / (2.0 * nn), half = z * std::sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn));
  // At k = 0 (k = n) the lower (upper) end is exactly 0 (1); computed, it would carry a rounding error.
  return {k == 0 ? 0.0 : (centre - half) / (1.0 + z2 / nn), k == n ? 1.0 : (centre + half) / (1.0 + z2 / nn)};
}

std::size_t fragment_fraction_bin(double f) {
  const auto& e = kFragmentFractionEdges;
  const auto hi = static_cast<std::size_t>(std::upper_bound(e.begin(), e.end(), f) - e.begin());
  return std::clamp<std::size_t>(hi, 1, e.size() - 1) - 1;
}

namespace {

// Every break of `outcomes` has its fragments' mass fractions in `fractions`.
bool breaks_have_fractions(const std::vector<PairOutcome>& outcomes, const std::vector<std::vector<double>>& fractions) {
  for (std::size_t k = 0; k < outcomes.size(); ++k)
    if (outcomes[k] == PairOutcome::brk && (k >= fractions.size() || fractions[k].empty())) return false;
  return true;
}

// Adds the fragments of one break (mass fractions f) to the sums of node i; divides by the breaks at the end.
void add_fragment_fractions(OutcomeGridResult& r, std::size_t i, const std::vector<double>& f) {
  const std::size_t nb = kFragmentFractionEdges.size() - 1;
  for (double x : f) {
    const std::size_t b = fragment_fraction_bin(x);
    r.fragment_number[i * nb + b] += 1.0;
    r.fragment_mass[i * nb + b] += x;
  }
}

void mean_fragment_fractions(OutcomeGridResult& r) {
  const std::size_t nb = kFragmentFractionEdges.size() - 1;
  for (std::size_t k = 0; k < r.fragment_number.size(); ++k) {
    const std::int64_t n = r.breaks[k / nb];
    r.fragment_number[k] = n > 0 ? r.fragment_number[k] / static_cast<double>(n) : std::nan("");
    r.fragment_mass[k] = n > 0 ? r.fragment_mass[k] / static_cast<double>(n) : std::nan("");
  }
}

}  // namespace

OutcomeGridResult tabulate_outcomes(const OutcomeGridSpec& spec, const std::vector<PairOutcome>& outcomes,
                                    const std::vector<double>& fragments, const std::vector<double>& largest,
                                    const std::vector<std::vector<double>>& fractions) {
  OutcomeGridResult r;
  r.spec = spec;
  const std::size_t n = spec.nodes();
  r.sticks.assign(n, 0);
  r.bounces.assign(n, 0);
  r.breaks.assign(n, 0);
  r.impacts.assign(n, 0);
  if (spec.aggregates()) {
    r.fragments.assign(n, 0.0);
    r.largest_fraction.assign(n, 0.0);
  }
  const bool distribution = spec.aggregates() && breaks_have_fractions(outcomes, fractions);
  if (distribution) {
    r.fragment_number.assign(n * (kFragmentFractionEdges.size() - 1), 0.0);
    r.fragment_mass.assign(n * (kFragmentFractionEdges.size() - 1), 0.0);
  }
  const auto jobs = outcome_impacts(spec);
  for (std::size_t k = 0; k < jobs.size() && k < outcomes.size(); ++k) {
    const OutcomeImpact& j = jobs[k];
    const std::size_t mirror = j.i1 == j.i2 && j.c1 == j.c2 && j.m1 == j.m2 ? 1 : 2;
    for (std::size_t m = 0; m < mirror; ++m) {
      const std::size_t i = m == 0 ? r.index(j.iv, j.i1, j.i2, j.c1, j.c2, j.ik, j.m1, j.m2)
                                   : r.index(j.iv, j.i2, j.i1, j.c2, j.c1, j.ik, j.m2, j.m1);
      ++r.impacts[i];
      ++(outcomes[k] == PairOutcome::stick ? r.sticks : outcomes[k] == PairOutcome::bounce ? r.bounces : r.breaks)[i];
      if (spec.aggregates() && outcomes[k] == PairOutcome::brk) {
        r.fragments[i] += fragments.at(k);
        r.largest_fraction[i] += largest.at(k);
        if (distribution) add_fragment_fractions(r, i, fractions[k]);
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
  mean_fragment_fractions(r);
  return r;
}

}  // namespace agglo::impact
