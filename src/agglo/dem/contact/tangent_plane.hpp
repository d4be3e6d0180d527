#pragma once
// Spring displacements stored in the tangent plane of a contact follow the plane as the pair
// rotates: the component along the new normal is removed and the length kept (Marshall 2009).
#include <cmath>

#include "agglo/core/vec3.hpp"
#include "agglo/dem/contact/lanes.hpp"

namespace agglo::dem::contact {

inline void rotate_into_plane(Vec3& xi, const Vec3& n) {
  double len2 = norm2(xi);
  if (len2 == 0.0) return;
  xi -= dot(xi, n) * n;
  double l2 = norm2(xi);
  if (l2 > 0.0) xi *= std::sqrt(len2 / l2);
}

// Lane form of rotate_into_plane (lanes.hpp): xi rotated into the plane normal to n.
template <class T>
[[gnu::always_inline]] inline lanes::V3<T> rotated_into_plane(const lanes::V3<T>& xi, const lanes::V3<T>& n) {
  using namespace lanes;
  const T len2 = norm2(xi);
  const V3<T> p = xi - dot(xi, n) * n;
  const T l2 = norm2(p);
  const V3<T> scaled = p * sqrt(len2 / l2);
  return select(len2 == 0.0, xi, select(l2 > 0.0, scaled, p));
}

}  // namespace agglo::dem::contact
