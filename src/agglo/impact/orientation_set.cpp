#include "agglo/impact/orientation_set.hpp"

#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::impact {

namespace {

double frac(double x) { return x - std::floor(x); }

}  // namespace

StratifiedOrientation stratified_orientation(int k, int m) {
  const double golden = 0.5 * (1.0 + std::sqrt(5.0));
  const double two_pi = 2.0 * constants::pi;
  const double cos_theta = 1.0 - (2.0 * k + 1.0) / m;
  const double theta = std::acos(cos_theta), sin_theta = std::sin(theta);
  const double phi = two_pi * frac(k / golden);
  StratifiedOrientation o;
  o.roll = two_pi * frac(0.5 + k * std::sqrt(3.0));
  o.direction = {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
  const Vec3 ex{1.0, 0.0, 0.0}, ey{0.0, 1.0, 0.0}, ez{0.0, 0.0, 1.0};
  const Rotation face = compose(rotation_about(ez, -phi), rotation_about(ey, -theta - 0.5 * constants::pi));
  o.rotation = compose(face, rotation_about(ex, o.roll));
  return o;
}

std::vector<StratifiedOrientation> stratified_orientations(int m) {
  std::vector<StratifiedOrientation> set;
  for (int k = 0; k < m; ++k) set.push_back(stratified_orientation(k, m));
  return set;
}

}  // namespace agglo::impact
