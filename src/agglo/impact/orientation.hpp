#pragma once
// Orientation of the agglomerate towards the projectile (docs/dem.md, "Orientation of the
// agglomerate"). The projectile moves along +x with its lateral offset along y; an orientation is a
// proper rigid rotation (det = +1) of the agglomerate about its centroid, so every contact keeps its
// overlap and every particle keeps its charge. Named orientations of the built-in shapes
// (agglomerate.orientation), with L the centre distance of touching neighbours:
//   tetrahedron, built with the hit edge 0-1 along z at x = -h and edge 2-3 along y at x = +h,
//   h = L/(2 sqrt 2); circumradius R_c = L sqrt(3/8):
//     edge_across  as built: hit edge 0-1 along z, so the offset (y) runs across the edge;
//     edge_along   90 deg about +x: hit edge 0-1 along y (particle 0 at +y), the offset runs along it;
//     face         -atan(sqrt 2) about +z: face 0-1-2 normal to x at x = -R_c/3 faces the projectile
//                  (edge 0-1 along z on its +y side, particle 2 on its -y side), vertex 3 on the +x axis;
//     vertex       pi - atan(sqrt 2) about +z: vertex 3 on the -x axis at x = -R_c points at the
//                  projectile, face 0-1-2 at x = +R_c/3 (particle 2 on the +y side).
//   square, built 2x2 in the x-y plane with side 0-3 along y at x = -L/2:
//     edge_along   as built: side 0-3 along y faces the projectile, the offset runs along it (in the plane);
//     edge_across  90 deg about +x: the square in the x-z plane, side 0-3 along z at x = -L/2, the
//                  offset runs across it (out of the plane);
//     face         90 deg about +y: the square in the y-z plane (normal along x), sides along y and z;
//                  the projectile aims at the centre of the 2x2 ring plus the offset (towards side 2-3);
//     vertex       -45 deg about +z: diagonal 0-2 along x, corner 0 at x = -L/sqrt 2 points at the
//                  projectile, the offset in the plane (towards particle 3).
// Each shape's original orientation (edge_across for the tetrahedron, edge_along for the square) is
// the identity and leaves the built positions untouched.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "agglo/core/rotation.hpp"
#include "agglo/core/vec3.hpp"
#include "agglo/dem/particles.hpp"

namespace agglo::impact {

// Rotation, rotation_about and compose: core/rotation.hpp.

// The orientation of a built-in shape ("tetrahedron", "square"); nullopt for the shape's original
// orientation or an empty name (no rotation). Throws std::invalid_argument for an unknown name.
std::optional<Rotation> named_orientation(std::string_view shape, std::string_view orientation);
// The shape's original orientation: "edge_across" (tetrahedron), "edge_along" (square), "" otherwise.
std::string original_orientation(std::string_view shape);

// Rotates particles 0..n-1 (all if n = 0) rigidly about their centroid: positions, velocities and
// angular velocities.
void rotate_about_centroid(dem::Particles& p, const Rotation& r, std::size_t n = 0);

}  // namespace agglo::impact
