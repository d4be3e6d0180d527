#pragma once
// Built-in agglomerates and the projectile (docs/model.md §A.3). Contacts start at the JKR equilibrium
// overlap delta0 = a0^2/(3R) (zero elastic force). The projectile (last particle) starts a surface gap
// of gap_radii * r_p before the agglomerate and moves along +x towards its centroid, offset along y.
//   tetrahedron: regular, edge (0,1) along z facing the projectile; charges +,-,+,-.
//   square:      2x2 in the x-y plane, side (0,3) facing the projectile; charges +,-,+,- round the ring.
// agglomerate.orientation then rotates the shape rigidly about its centroid (orientation.hpp lists
// the geometry of each orientation); particles keep their indices and charges.
//   fractal, bpca, bcca, file: the structure builder's primaries (impact/structure_target.hpp).
#include "agglo/impact/impact_case.hpp"
#include "agglo/dem/particles.hpp"

namespace agglo::impact {

// Agglomerate only (index 0..N-1), at rest, centroid at the origin.
dem::Particles build_agglomerate(const ImpactCase& c);
// Appends the projectile (index N; an aggregate projectile: indices N .. N + primaries - 1, all at
// speed v along +x, its surface gap_radii r_p before the agglomerate's, its centroid offset along y).
void add_projectile(dem::Particles& p, const ImpactCase& c, double speed);

// The k-th sampled orientation of an aggregate projectile (breakup.orientations; k = 0 also for
// projectile.orientation = "random"): a uniform random rotation drawn from projectile.seed and k.
Rotation projectile_orientation(const ImpactCase& c, int k);

}  // namespace agglo::impact
