#include "agglo/electrostatics/spectral/degree.hpp"

#include <algorithm>
#include <cmath>

namespace agglo::es::sh {

namespace {
// Limit point inside the second sphere, measured from the centre of the first (radius a).
double far_limit(double a, double b, double t) {
  double s = (t * t + a * a - b * b) / t;
  double disc = std::max(0.0, s * s - 4 * a * a);
  return 0.5 * (s + std::sqrt(disc));
}
double prefactor(double a, double b, double t) {
  double h = (t - a - b) / std::min(a, b);
  return std::clamp(80.0 * h, 1.0, 8.0);
}

}  // namespace

double rate(const PairRatio& r) {
  double m = std::max(r.rho_a, r.rho_b);
  return m * m;
}

PairRatio limit_ratios(double a, double b, double t) {
  return {a / far_limit(a, b, t), b / far_limit(b, a, t), prefactor(a, b, t)};
}

int degree_for(const PairRatio& r, double tol) {
  double q = rate(r);
  if (q <= 0.0) return 1;
  if (q >= 1.0) return 1 << 20;
  double L = std::log(tol / r.C) / std::log(q);
  return std::max(1, static_cast<int>(std::ceil(L)));
}

double error_estimate(const PairRatio& r, int L) { return r.C * std::pow(rate(r), L); }

}  // namespace agglo::es::sh
