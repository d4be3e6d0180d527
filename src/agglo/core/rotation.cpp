#include "agglo/core/rotation.hpp"

#include <cmath>

namespace agglo {

Rotation rotation_about(const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  const Vec3& a = axis;
  Rotation r;
  r.m[0] = {c + t * a.x * a.x, t * a.x * a.y - s * a.z, t * a.x * a.z + s * a.y};
  r.m[1] = {t * a.y * a.x + s * a.z, c + t * a.y * a.y, t * a.y * a.z - s * a.x};
  r.m[2] = {t * a.z * a.x - s * a.y, t * a.z * a.y + s * a.x, c + t * a.z * a.z};
  return r;
}

Rotation compose(const Rotation& a, const Rotation& b) {
  Rotation r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = b.m[i].x * a.m[0][j] + b.m[i].y * a.m[1][j] + b.m[i].z * a.m[2][j];
  return r;
}

}  // namespace agglo
