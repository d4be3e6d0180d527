#pragma once
// Rotations of 3-vectors as 3x3 matrices (rows m[i]: x' = m x): Rodrigues' formula for a rotation by an
// angle about a unit axis, and composition. Used by the impact orientations and the structure builder.
#include <array>

#include "agglo/core/vec3.hpp"

namespace agglo {

struct Rotation {
  std::array<Vec3, 3> m{Vec3{1.0, 0.0, 0.0}, Vec3{0.0, 1.0, 0.0}, Vec3{0.0, 0.0, 1.0}};
  Vec3 apply(const Vec3& x) const { return {dot(m[0], x), dot(m[1], x), dot(m[2], x)}; }
};

// Rotation by `angle` [rad] about the unit vector `axis` (right-handed, Rodrigues' formula):
//   R = cos(angle) I + sin(angle) [axis]_x + (1 - cos(angle)) axis axis^T
Rotation rotation_about(const Vec3& axis, double angle);
// a then b: x' = b (a x).
Rotation compose(const Rotation& a, const Rotation& b);

}  // namespace agglo
