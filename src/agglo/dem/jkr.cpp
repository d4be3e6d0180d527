#include "agglo/dem/jkr.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::dem {

namespace {
const double kCbrt6 = std::cbrt(6.0);
const double kSMin = 1.0 / std::cbrt(6.0);  // s at delta = -delta_C (dd/ds = 0)
}  // namespace

JkrPair JkrPair::make(double R, double Estar, double gamma) {
  JkrPair p;
  p.R = R;
  p.Estar = Estar;
  p.gamma = gamma;
  p.Fc = 3.0 * constants::pi * gamma * R;
  p.a0 = std::cbrt(9.0 * constants::pi * gamma * R * R / Estar);
  p.deltaC = p.a0 * p.a0 / (2.0 * kCbrt6 * R);
  return p;
}

double JkrPair::delta_of_a(double a) const {
  return a * a / R - 2.0 * std::sqrt(constants::pi * gamma * a / Estar);
}

double JkrPair::a_of_delta(double delta, double a_guess) const {
  const double d = delta / (kCbrt6 * deltaC);  // target of f(s) = 2 s^4 - 4/3 s
  if (d <= -kSMin) return kSMin * kSMin * a0;  // at/below the break point: the turning point
  // f is convex and increasing for s >= s_min. From a warm start near the root Newton converges in a
  // few steps from either side (from the left it lands right of the root, then decreases
  // monotonically). Without a usable guess (or close to the turning point, where f' -> 0) start from
  // an upper bound of the root.
  double s;
  if (a_guess > 0.0 && a_guess > 1.2 * kSMin * kSMin * a0) {
    s = std::sqrt(a_guess / a0);
  } else {
    s = std::max(1.0, std::sqrt(std::sqrt(std::max(d, 0.0) / 2.0 + 1.0)) + 0.5);
  }
  // Quadratic convergence; near the turning point (d -> -s_min) it degrades to linear, hence the cap.
  for (int it = 0; it < 100; ++it) {
    double s3 = s * s * s;
    double f = 2.0 * s3 * s - 4.0 / 3.0 * s - d;
    double fp = 8.0 * s3 - 4.0 / 3.0;
    double s_new = std::max(s - f / fp, kSMin);
    double change = std::abs(s_new - s);
    s = s_new;
    if (change <= 4e-16 * s) break;
  }
  return s * s * a0;
}

double JkrPair::force_of_a(double a) const {
  double x = a / a0;
  return 4.0 * Fc * (x * x * x - x * std::sqrt(x));
}

}  // namespace agglo::dem
