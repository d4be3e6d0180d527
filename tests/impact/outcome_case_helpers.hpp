#pragma once
// Case texts shared by the outcome-table tests (test_outcome_grid.cpp, test_outcome_charges.cpp,
// test_outcome_aggregates.cpp, test_outcome_primary_radii.cpp): the seed material of the shipped outcome cases
// (cases/outcomes_sphere_sphere.toml: E = 1 GPa, nu = 0.33, gamma = 0.01 J/m^2, e = 0.7) and two BPCA partners
// of 0.5 um primaries (cases/outcomes_aggregates.toml, smaller grid) parsed as agglo outcomes parses them.
#include <string>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/impact/outcome_aggregates.hpp"

namespace agglo::impact::test {

// [material] of the seed material with the given friction coefficient.
inline std::string seed_material(const std::string& friction) {
  return "\n[material]\ndensity = 2500.0\nyoungs_modulus = 1e9\npoisson_ratio = 0.33\nsurface_energy = 0.01\n"
         "restitution = 0.7\nfriction = " +
         friction + "\n";
}

// Two BPCA partners of 0.5 um primaries; `extra` goes into [agglomerate], `grid` into [outcome_grid].
inline std::string aggregate_pair_case(const std::string& grid, const std::string& extra = "") {
  return seed_material("0.3") + "[agglomerate]\nshape = \"bpca\"\nradius = 0.5e-6\n" + extra +
         "[projectile]\nshape = \"bpca\"\ngap_radii = 0.5\n[time]\nafter_contact = 2e-6\n[outcome_grid]\n" + grid;
}

struct AggregateGrid {
  ImpactCase dem;
  OutcomeGridSpec grid;
};

// The aggregate pair case parsed and checked (unknown keys refused).
inline AggregateGrid parse_aggregate_grid(const std::string& grid, const std::string& extra = "") {
  Config cfg = Config::from_string(aggregate_pair_case(grid, extra), "agg.toml");
  AggregateGrid p{parse_impact_case(cfg, true), parse_outcome_grid(cfg.root())};
  check_aggregate_pair(cfg.root(), p.dem, p.grid);
  cfg.check_unknown_keys();
  return p;
}

// Every impact of the grid run on one thread and classified; per impact the pair's primary masses and its
// fragments, in the order of outcome_impacts.
struct AggregateImpacts {
  std::vector<std::vector<double>> masses;
  std::vector<PairFragments> fragments;
  std::vector<PairOutcome> outcomes() const {
    std::vector<PairOutcome> o;
    for (const auto& f : fragments) o.push_back(f.outcome);
    return o;
  }
};
inline AggregateImpacts run_aggregate_grid(const AggregateGrid& p) {
  AggregateImpacts r;
  for (const auto& j : outcome_impacts(p.grid)) {
    const ImpactCase c = outcome_case(p.dem, p.grid, j);
    const ImpactOutcome o = run_impact(c, outcome_launch_speed(p.grid, j));
    r.masses.push_back(pair_masses(c));
    r.fragments.push_back(classify_aggregate_pair(o.components, r.masses.back(), c.agglomerate.structure.size()));
  }
  return r;
}

}  // namespace agglo::impact::test
