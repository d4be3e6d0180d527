#pragma once
// Aggregate-aggregate collision outcomes on the grid of agglo outcomes (docs/outcomes.md "Aggregate
// tables"): `outcome_grid.primaries` = N_1 < N_2 < ... replaces `outcome_grid.diameters`. Both partners are
// built by the structure builder (agglomerate.shape and projectile.shape = fractal | bpca | bcca, with
// their D_f, k_f; one primary radius a for both, monodisperse), the target with N_1 and the projectile
// with N_2 primaries of node (N_1, N_2). The table's size axes are the volume-equivalent diameters
//   d = 2 a N^(1/3)  [m]
// With outcome_grid.primary_radii a_0 < a_1 < ... each partner has its own primary radius a_m (node axes
// primary_radius_1, primary_radius_2) on the common size axis d_k = 2 a_0 N_k^(1/3): N_k (a_0 / a_m)^3
// primaries of a_m, a whole number >= 2 (else refused), so the nodes (d, a) are a product grid.
// (the diameters of the DSMC's compact samples of that mass, which the DSMC table reader interpolates
// over), and the impact parameter b is sampled as for spheres relative to r_1 + r_2 = a (N_1^(1/3) +
// N_2^(1/3)), with the launch speed v_n / sqrt(1 - (b / (r_1 + r_2))^2) (the normal speed of the two
// volume-equivalent spheres at contact). Each impact builds both structures anew, with builder seeds and
// a random rigid rotation of the projectile drawn from (outcome_grid.seed, node, sample), so the ensemble
// averages over structures, orientations and offsets.
// Outcome of one impact from the contact graph at the end (all particles, experiment.hpp's components):
//   fragments = its connected components; stick = one component; bounce = two components that are exactly
//   the two original partners (target primaries [0, N_1), projectile [N_1, N_1 + N_2)); break = anything
//   else. A pair that never touched ends as its two partners and counts as a bounce.
// Fragment statistics of an impact: number of components and the mass fraction of the largest,
// m_largest / M with M = sum of all primary masses, and every fragment's mass fraction m / M.
#include <cstddef>
#include <vector>

#include "agglo/impact/outcome_grid.hpp"

namespace agglo::impact {

// ConfigError unless both partners are builder aggregates (fractal, bpca or bcca) of one monodisperse
// primary radius, without a wall, time.dt = 0, and every primary radius gives whole counts; fills
// s.diameters with 2 a N^(1/3) of s.primaries (a = primary_radii[0] when given).
void check_aggregate_pair(const ConfigSection& root, const ImpactCase& c, OutcomeGridSpec& s);

// The case of one aggregate impact of the grid: both structures built with the impact's seeds, the
// projectile rotated, the offset b in units of the primary radius.
ImpactCase aggregate_outcome_case(const ImpactCase& base, const OutcomeGridSpec& s, const OutcomeImpact& j);

struct PairFragments {
  PairOutcome outcome = PairOutcome::stick;
  int fragments = 1;              // components of the final contact graph
  double largest_fraction = 1.0;  // mass of the largest / total mass [1]
  double fragment_mass = 0.0;     // sum of the fragments' masses [kg] (= the total mass)
  std::vector<double> fractions;  // each fragment's mass / total mass [1], in the order of the components
};

// Classification above. `components`: the final contact-graph components (each particle in exactly one;
// std::invalid_argument otherwise), `masses` [kg] per particle, the first `n_target` the target's.
PairFragments classify_aggregate_pair(const std::vector<std::vector<int>>& components,
                                      const std::vector<double>& masses, std::size_t n_target);

// Masses [kg] of the particles of one impact of `c` in the order of the DEM system (target, projectile).
std::vector<double> pair_masses(const ImpactCase& c);

}  // namespace agglo::impact
