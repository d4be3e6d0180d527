#pragma once
// Tunable fractal aggregates (docs/model.md §S.2): every cluster of n >= 3 primaries obeys
//   n = k_f (R_g / abar)^D_f,   R_g = point-mass radius of gyration [m] (each primary weight 1),
// abar = geometric mean of the aggregate's primary radii (structure/primaries.hpp) [m].
// Method (after Filippov, Zurita & Rosner, J. Colloid Interface Sci. 229 (2000) 261, and FracVAL, Moran
// et al., Comput. Phys. Commun. 239 (2019) 225): primaries are split into sub-clusters of at most
// kSubclusterSize, each grown by tunable particle-cluster aggregation (PCA) from a touching dimer; the
// sub-clusters are then joined pairwise, level by level, by tunable cluster-cluster aggregation (CCA).
// Joining clusters 1 and 2 (m_1, m_2 primaries, M = m_1 + m_2) puts their centroids at the distance
//   Gamma^2 = M / (m_1 m_2) (M R_g,M^2 - m_1 R_g,1^2 - m_2 R_g,2^2),  R_g,M from the law,
// (a monomer has R_g = 0) which makes the joined cluster's R_g the law's exactly; a touching pair
// (i of 1, j of 2) that can span Gamma is chosen at random, then the angles, and the placement is
// kept when nothing overlaps. Contacts are exact to rounding (|d - r_i - r_j| ~ 1e-15 r).
// Errors (BuildError, naming the key): D_f outside kMinFractalDimension..kMaxFractalDimension, or no
// placement found after kMaxRestarts restarts of a sub-cluster or kMaxPairTries pairs of a join.
#include <cstdint>

#include "agglo/structure/aggregate.hpp"

namespace agglo::structure {

struct FractalRequest {
  int primaries = 64;              // N >= 2
  double fractal_dimension = 1.8;  // D_f
  double fractal_prefactor = 1.3;  // k_f
  double radius = 10e-6;           // a_g, geometric-mean primary radius [m]
  double radius_std = 1.0;         // sigma_g >= 1 (1 = monodisperse)
  std::uint64_t seed = 1;
};

inline constexpr int kSubclusterSize = 16;
inline constexpr double kMinFractalDimension = 1.5;
inline constexpr double kMaxFractalDimension = 2.5;
inline constexpr int kMaxRestarts = 200;
inline constexpr int kMaxPairTries = 400;

// Centroid at the origin; identical for identical requests (one Philox stream per seed).
Aggregate build_fractal(const FractalRequest& q);

// R_g of n primaries by the law: abar (n / k_f)^(1/D_f) [m].
double law_radius_of_gyration(double n, double k_f, double d_f, double abar);

}  // namespace agglo::structure
