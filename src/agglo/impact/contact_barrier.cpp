#include "agglo/impact/contact_barrier.hpp"

#include <cmath>
#include <functional>

namespace agglo::impact {

namespace {

const double kCbrt6Barrier = std::cbrt(6.0);
const double kXBreak = 1.0 / (kCbrt6Barrier * kCbrt6Barrier);  // x_b = 6^(-2/3): delta = -delta_C
const double kXForceMin = std::pow(2.0, -2.0 / 3.0);          // F = -F_C

double overlap_of_x(double x) { return kCbrt6Barrier * (2.0 * x * x - 4.0 / 3.0 * std::sqrt(x)); }
double force_of_x(double x) { return 4.0 * (x * x * x - x * std::sqrt(x)); }

// The root of the monotonic g on [lo, hi] (g(lo) and g(hi) of opposite signs), to round-off.
double monotonic_root(const std::function<double(double)>& g, double lo, double hi) {
  const bool rising = g(hi) > g(lo);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    ((g(mid) < 0.0) == rising ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double jkr_potential(double x) {
  return 4.0 * kCbrt6Barrier * (0.8 * std::pow(x, 5) - 4.0 / 3.0 * std::pow(x, 3.5) + x * x / 3.0);
}

double loaded_potential(double x, double l) { return jkr_potential(x) - l * overlap_of_x(x); }

double break_x(double s) {
  return s >= 1.0 ? kXBreak : monotonic_root([s](double x) { return overlap_of_x(x) + s; }, kXBreak, 1.0);
}

double formation_x() { return std::pow(2.0 / 3.0, 2.0 / 3.0); }  // 2 x^2 = 4/3 x^(1/2)

LoadedContact loaded_contact(double l, double s) {
  LoadedContact c;
  if (!(l > -1.0)) return c;  // pulled apart at least as hard as the pull-off force: no stable contact
  double hi = 1.0;
  while (force_of_x(hi) < l) hi *= 2.0;
  c.x_min = monotonic_root([l](double x) { return force_of_x(x) - l; }, kXForceMin, hi);
  // The break point on the stable branch (delta increases with x there).
  const double xs = break_x(s);
  c.x_peak = xs;
  if (xs < kXForceMin && l < force_of_x(xs))  // psi rises from the break point until F = L (falling branch)
    c.x_peak = monotonic_root([l](double x) { return force_of_x(x) - l; }, xs, kXForceMin);
  c.barrier = loaded_potential(c.x_peak, l) - loaded_potential(c.x_min, l);
  return c;
}

}  // namespace agglo::impact
