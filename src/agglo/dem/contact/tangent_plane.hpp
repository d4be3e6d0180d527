#pragma once
// Spring displacements stored in the tangent plane of a contact follow the plane as the pair
// rotates: the component along the new normal is removed and the length kept (Marshall 2009).
#include <cmath>

#include "agglo/core/vec3.hpp"

namespace agglo::dem::contact {

inline void rotate_into_plane(Vec3& xi, const Vec3& n) {
  double len2 = norm2(xi);
  if (len2 == 0.0) return;
  xi -= dot(xi, n) * n;
  double l2 = norm2(xi);
  if (l2 > 0.0) xi *= std::sqrt(len2 / l2);
}

}  // namespace agglo::dem::contact
