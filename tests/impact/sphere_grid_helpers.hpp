#pragma once
// Shared helpers of the sphere-sphere outcome-grid tests (test_outcome_grid.cpp, test_outcome_charges.cpp):
// a case text parsed as agglo outcomes parses it, and its grid run impact by impact on one thread.
#include <string>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/impact/outcome_grid.hpp"

namespace agglo::impact::test {

struct SphereGrid {
  ImpactCase dem;
  OutcomeGridSpec grid;
};

// `toml`: a one-sphere list target hit by a sphere, with [outcome_grid] (unknown keys refused).
inline SphereGrid parse_sphere_grid(const std::string& toml) {
  Config cfg = Config::from_string(toml, "pair.toml");
  SphereGrid p{parse_impact_case(cfg, true), {}};
  check_sphere_sphere(cfg.root(), p.dem);
  p.grid = parse_outcome_grid(cfg.root());
  cfg.check_unknown_keys();
  return p;
}

// Every impact of the grid run and classified (classify_pair), tabulated.
inline OutcomeGridResult run_sphere_grid(const SphereGrid& p) {
  std::vector<PairOutcome> out;
  for (const auto& j : outcome_impacts(p.grid))
    out.push_back(classify_pair(run_impact(outcome_case(p.dem, p.grid, j), outcome_launch_speed(p.grid, j))));
  return tabulate_outcomes(p.grid, out);
}

}  // namespace agglo::impact::test
