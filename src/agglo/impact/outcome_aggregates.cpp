#include "agglo/impact/outcome_aggregates.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "agglo/core/rng.hpp"
#include "agglo/core/settings_outcomes.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/structure_target.hpp"

namespace agglo::impact {

namespace {

constexpr std::uint64_t kPartnerStream = 0x706172746e657273ULL;  // "partners": the builder seeds' stream

bool is_generated_shape(const std::string& shape) { return shape == "fractal" || shape == "bpca" || shape == "bcca"; }

// A builder seed drawn from `rng` (non-negative, as agglomerate.seed).
long long draw_seed(CounterRng& rng) { return static_cast<long long>(rng.bits() >> 2); }

// ConfigError unless every primary radius a_m of outcome_grid.primary_radii gives every size d_k a whole
// count N_k (a_0 / a_m)^3 >= 2 (within 1e-9 relative): the common size axis (outcome_grid.hpp).
void check_whole_counts(const ConfigSection& root, const OutcomeGridSpec& s) {
  const auto& k = settings::outcomes_settings().grid;
  for (std::size_t m = 1; m < s.primary_radii.size(); ++m)
    for (std::size_t i = 0; i < s.primaries.size(); ++i) {
      const double ratio = s.primary_radii[0] / s.primary_radii[m];
      const double n = s.primaries[i] * ratio * ratio * ratio;
      if (std::abs(n - std::round(n)) > 1e-9 * n || std::round(n) < 2.0)
        k.primary_radii.reject(
            k.t.open(root),
            fmt::format("value {} = {:g} m gives {:.6g} primaries at {} = {} (the volume-equivalent diameter "
                        "2 a_0 N^(1/3) of {:g} m): allowed are radii a_0 (N / n)^(1/3) with n a whole number >= 2 "
                        "for every N (e.g. a_0 2^(1/3) with even counts)",
                        m, s.primary_radii[m], n, k.primaries.dotted(), s.primaries[i], s.primary_radii[0]));
    }
}

}  // namespace

void check_aggregate_pair(const ConfigSection& root, const ImpactCase& c, OutcomeGridSpec& s) {
  const auto& k = impact_keys();
  const auto why = fmt::format("{} tabulates aggregate-aggregate impacts: use \"fractal\", \"bpca\" or \"bcca\"",
                               settings::outcomes_settings().grid.primaries.dotted());
  const ConfigSection ag = k.agglomerate.t.open(root), pj = k.projectile.t.open(root);
  if (!is_generated_shape(c.agglomerate.shape)) k.agglomerate.shape.reject(ag, why);
  if (!is_generated_shape(c.projectile.shape)) k.projectile.shape.reject(pj, why);
  if (c.projectile.body.radius != c.agglomerate.radius)
    k.projectile.radius.reject(pj, fmt::format("the table's diameters 2 a N^(1/3) need one primary radius a: "
                                               "remove it or set {}", k.agglomerate.radius.dotted()));
  if (c.agglomerate.radius_std != 1.0) k.agglomerate.builder.radius_std.reject(ag, "must be 1 (monodisperse primaries)");
  if (c.projectile.body.radius_std != 1.0) k.projectile.builder.radius_std.reject(pj, "must be 1 (monodisperse primaries)");
  if (c.dem.dt > 0.0)
    k.time.dt.reject(k.time.t.open(root), fmt::format("agglo outcomes takes each node's step from its contact period: "
                                                      "set 0 and choose {}",
                                                      k.time.steps_per_period.dotted()));
  if (!c.dem.walls.empty()) k.wall.t.fail(root, "agglo outcomes tabulates pair impacts: remove the [wall] table");
  s.primary_radius = s.primary_radii.empty() ? c.agglomerate.radius : s.primary_radii[0];
  s.diameters.clear();
  for (int n : s.primaries) s.diameters.push_back(2.0 * s.primary_radius * std::cbrt(static_cast<double>(n)));
  check_whole_counts(root, s);
}

ImpactCase aggregate_outcome_case(const ImpactCase& base, const OutcomeGridSpec& s, const OutcomeImpact& j) {
  ImpactCase c = base;
  // Keyed by the pair of sizes and the sample, not the speed: every speed hits the same structures.
  const std::uint64_t pair = j.i1 * s.sizes() + j.i2;
  CounterRng rng(s.seed, kPartnerStream, pair * static_cast<std::uint64_t>(s.impacts) + static_cast<std::uint64_t>(j.sample));
  c.agglomerate.primaries = s.partner_primaries(j.i1, j.m1);
  c.agglomerate.radius = s.partner_radius(j.m1);  // each partner's own primary radius
  c.agglomerate.seed = draw_seed(rng);
  c.agglomerate.structure = build_structure(c.agglomerate);
  auto& body = c.projectile.body;
  body.primaries = s.partner_primaries(j.i2, j.m2);
  body.radius = s.partner_radius(j.m2);
  body.seed = draw_seed(rng);
  body.structure = build_structure(body);
  c.projectile.rotation = projectile_orientation(c, 0);  // drawn from the body's seed
  const double r1 = 0.5 * s.diameters[j.i1], r2 = 0.5 * s.diameters[j.i2];
  c.projectile.offset_radii = j.b_fraction * (r1 + r2) / c.agglomerate.radius;
  return c;
}

PairFragments classify_aggregate_pair(const std::vector<std::vector<int>>& components,
                                      const std::vector<double>& masses, std::size_t n_target) {
  std::vector<char> seen(masses.size(), 0);
  PairFragments f;
  f.fragments = static_cast<int>(components.size());
  double total = 0.0, largest = 0.0;
  bool target_alone = false;
  std::vector<double> component_mass;
  for (const auto& g : components) {
    double m = 0.0;
    std::size_t targets = 0;
    for (int i : g) {
      if (i < 0 || static_cast<std::size_t>(i) >= masses.size() || seen[static_cast<std::size_t>(i)])
        throw std::invalid_argument(fmt::format("particle {} is outside the {} particles or in two components", i,
                                                masses.size()));
      seen[static_cast<std::size_t>(i)] = 1;
      m += masses[static_cast<std::size_t>(i)];
      targets += static_cast<std::size_t>(i) < n_target;
    }
    target_alone = target_alone || (targets == n_target && g.size() == n_target);
    f.fragment_mass += m;
    largest = std::max(largest, m);
    component_mass.push_back(m);
  }
  for (double m : masses) total += m;
  for (double m : component_mass) f.fractions.push_back(m / total);
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (!seen[i]) throw std::invalid_argument(fmt::format("particle {} is in no component", i));
  f.largest_fraction = largest / total;
  f.outcome = f.fragments == 1 ? PairOutcome::stick
              : f.fragments == 2 && target_alone ? PairOutcome::bounce
                                                 : PairOutcome::brk;
  return f;
}

std::vector<double> pair_masses(const ImpactCase& c) {
  dem::Particles p;
  place_structure(c.agglomerate, c, p);
  place_structure(c.projectile.body, c, p);
  return p.m;
}

}  // namespace agglo::impact
