#include "agglo/structure/geometry.hpp"

#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::structure {

Vec3 random_direction(CounterRng& rng) {
  const double z = 2.0 * rng.uniform() - 1.0;
  const double phi = 2.0 * constants::pi * rng.uniform();
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

Rotation random_rotation(CounterRng& rng) {
  // Uniform axis for the new z, then a uniform spin about it: Haar measure on SO(3).
  const Vec3 z = random_direction(rng);
  const double spin = 2.0 * constants::pi * rng.uniform();
  return compose(rotation_taking({0.0, 0.0, 1.0}, z), rotation_about(z, spin));  // tilt, then spin about z
}

Rotation rotation_taking(const Vec3& from, const Vec3& to) {
  const Vec3 axis = cross(from, to);
  const double s = norm(axis), c = dot(from, to);
  if (s < 1e-14) {
    if (c > 0.0) return Rotation{};
    Vec3 p, q;
    orthonormal_pair(from, p, q);
    return rotation_about(p, constants::pi);
  }
  return rotation_about(axis / s, std::atan2(s, c));
}

void orthonormal_pair(const Vec3& n, Vec3& p, Vec3& q) {
  const Vec3 t = std::abs(n.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  p = cross(n, t);
  p /= norm(p);
  q = cross(n, p);
}

std::optional<Vec3> sphere_intersection_point(const Vec3& c1, double R1, const Vec3& c2, double R2, double phi) {
  const Vec3 d = c2 - c1;
  const double L = norm(d);
  if (L == 0.0 || L > R1 + R2 || L < std::abs(R1 - R2)) return std::nullopt;
  const Vec3 u = d / L;
  const double a = (L * L + R1 * R1 - R2 * R2) / (2.0 * L);
  const double h = std::sqrt(std::max(0.0, R1 * R1 - a * a));
  Vec3 p, q;
  orthonormal_pair(u, p, q);
  return c1 + a * u + h * (std::cos(phi) * p + std::sin(phi) * q);
}

std::optional<double> ray_sphere_hit(const Vec3& o, const Vec3& u, const Vec3& c, double s) {
  const Vec3 w = o - c;
  const double b = dot(w, u), cc = dot(w, w) - s * s;
  const double disc = b * b - cc;
  if (disc < 0.0) return std::nullopt;
  const double t = -b - std::sqrt(disc);
  if (t < 0.0) return std::nullopt;
  return t;
}

}  // namespace agglo::structure
