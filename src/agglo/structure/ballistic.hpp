#pragma once
// Ballistic aggregates (docs/model.md §S.3), compact and open kinetic structures:
//   BPCA (ballistic particle-cluster): primaries arrive one at a time along straight lines of isotropic
//     random direction and uniform random impact parameter over the disk that covers the cluster, and
//     stick where they first touch (Meakin 1984; D_f ~ 3 for large N, about 2.7-2.8 at N ~ 256);
//   BCCA (ballistic cluster-cluster): clusters of equal (or, for N not a power of two, nearly equal)
//     size are paired level by level; the second, randomly rotated, moves along a random line until it
//     first touches the first (Jullien & Kolb 1984; D_f ~ 1.9-2.0).
// Contacts are exact to rounding; no overlap. Radii as structure/primaries.hpp. Identical for a seed.
// BuildError("primaries") when a line misses kMaxMisses times in a row (does not happen for a finite
// cluster: a miss only redraws the line).
#include <cstdint>

#include "agglo/structure/aggregate.hpp"

namespace agglo::structure {

enum class Ballistic { particle_cluster, cluster_cluster };

struct BallisticRequest {
  Ballistic kind = Ballistic::particle_cluster;
  int primaries = 64;       // N >= 2
  double radius = 10e-6;    // a_g [m]
  double radius_std = 1.0;  // sigma_g
  std::uint64_t seed = 1;
};

inline constexpr int kMaxMisses = 100000;

// Centroid at the origin.
Aggregate build_ballistic(const BallisticRequest& q);

}  // namespace agglo::structure
