#pragma once
// Stratified, deterministic set of M rigid rotations covering SO(3) evenly, for the
// orientation-averaged break-up probability (breakup.orientations; docs/dem.md). A uniform (Haar)
// random rotation is a uniform impact direction d on the sphere times a uniform roll psi about it, so
// the set draws (cos theta, phi, psi) from a low-discrepancy point set of the unit cube instead of
// random numbers. Rotation k of M (k = 0..M-1):
//   cos theta_k = 1 - (2k + 1)/M           equal-area bands of the sphere, one direction in each;
//   phi_k = 2 pi frac(k / g),  g = (1 + sqrt 5)/2   the golden-angle spiral (spherical Fibonacci set);
//   psi_k = 2 pi frac(1/2 + k sqrt 3)       the roll about the impact axis;
//   d_k = (sin theta_k cos phi_k, sin theta_k sin phi_k, cos theta_k)   in the agglomerate's frame.
// The rotation turns d_k to -x (the side the projectile comes from) with the fixed rotation
// Ry(-theta_k - pi/2) Rz(-phi_k), then rolls the agglomerate by psi_k about the impact axis x.
// Why even: the spherical Fibonacci set is the usual even covering of the sphere (Swinbank & Purser
// 2006, QJRMS 132: 1769), one direction per equal-area band; 1/g and sqrt 3 are badly approximable
// and, with 1, linearly independent over the rationals, so (k/M, frac(k/g), frac(k sqrt 3)) is
// equidistributed in the cube (Weyl) and the rotations in SO(3). For M = 4..64 the first and second
// moments of the rotation matrices (Haar: 0 and delta delta/3) deviate on average a third and a
// half as much as those of M random rotations, the moments of d_k 4 % and 7 % as much. The
// direction matters most: with a small offset the roll only turns the offset about the impact axis.
#include <vector>

#include "agglo/impact/orientation.hpp"

namespace agglo::impact {

struct StratifiedOrientation {
  Vec3 direction;    // unit vector d_k in the agglomerate's frame that faces the projectile
  double roll = 0.0;  // psi_k [rad] about the impact axis
  Rotation rotation;  // maps the agglomerate's frame to the lab frame: rotation.apply(d_k) = -x
};

// Rotation k of the set of M (0 <= k < M).
StratifiedOrientation stratified_orientation(int k, int m);
std::vector<StratifiedOrientation> stratified_orientations(int m);

}  // namespace agglo::impact
