#include "agglo/sectional/initial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "agglo/core/constants.hpp"

namespace agglo::sectional {

namespace {
using acoustics::Distribution;
using acoustics::PopulationSpec;
using constants::pi;

// Phi(zb) - Phi(za) for za <= zb, from the tail that keeps the digits.
double normal_between(double za, double zb) {
  const double s = 1.0 / std::sqrt(2.0);
  if (za >= 0.0) return 0.5 * (std::erfc(za * s) - std::erfc(zb * s));
  if (zb <= 0.0) return 0.5 * (std::erfc(-zb * s) - std::erfc(-za * s));
  return 1.0 - 0.5 * std::erfc(-za * s) - 0.5 * std::erfc(zb * s);
}

double diameter_of(double v) { return std::cbrt(6.0 * v / pi); }

// 1 - (1 + t) e^(-t) for t >= 0 (its series for small t, where the difference cancels).
double one_minus_one_plus_t_exp(double t) {
  if (t > 0.05) return 1.0 - (1.0 + t) * std::exp(-t);
  double term = -t, sum = 0.0;  // (-t)^1 / 1!
  for (int n = 2; n <= 9; ++n) {
    term *= -t / n;  // (-t)^n / n!
    sum += (n - 1) * term;
  }
  return sum;
}

Moments lognormal(const PopulationSpec& p, double a, double b) {
  const double s = std::log(p.geometric_std), dg = p.geometric_mean_diameter;
  const double za = a > 0 ? std::log(diameter_of(a) / dg) / s : -std::numeric_limits<double>::infinity();
  const double zb = std::isinf(b) ? b : std::log(diameter_of(b) / dg) / s;
  const double N = p.number_concentration;
  return {N * normal_between(za, zb),
          N * pi / 6.0 * dg * dg * dg * std::exp(4.5 * s * s) * normal_between(za - 3.0 * s, zb - 3.0 * s)};
}

Moments exponential(const PopulationSpec& p, double a, double b) {
  const double v0 = p.mean_volume, N = p.number_concentration;
  const double ea = std::exp(-a / v0);
  if (std::isinf(b)) return {N * ea, N * (a + v0) * ea};
  const double t = (b - a) / v0;
  // e^-a/v0 - e^-b/v0 and (a + v0) e^-a/v0 - (b + v0) e^-b/v0, without cancellation.
  return {-N * ea * std::expm1(-t), N * v0 * ea * ((a / v0) * -std::expm1(-t) + one_minus_one_plus_t_exp(t))};
}

Moments point(double d, double number, double a, double b) {
  const double v = pi / 6.0 * d * d * d;
  return (v >= a && v < b) ? Moments{number, number * v} : Moments{};
}
}  // namespace

Moments population_moments(const PopulationSpec& p, double a, double b) {
  switch (p.distribution) {
    case Distribution::lognormal: return lognormal(p, a, b);
    case Distribution::exponential: return exponential(p, a, b);
    case Distribution::monodisperse: return point(p.diameter, p.number_concentration, a, b);
    case Distribution::table: {
      Moments m;
      double total = 0.0;
      for (double f : p.table_fractions) total += f;
      for (std::size_t k = 0; k < p.table_diameters.size(); ++k) {
        const Moments e = point(p.table_diameters[k], p.number_concentration * p.table_fractions[k] / total, a, b);
        m.number += e.number;
        m.volume += e.volume;
      }
      return m;
    }
  }
  return {};
}

Projection project(const Grid& g, const std::vector<PopulationSpec>& pops) {
  const std::size_t m = g.size();
  Projection pr;
  pr.n.assign(m, 0.0);
  for (const auto& p : pops) {
    const Moments lo = population_moments(p, 0.0, g.x.front());
    const Moments hi = population_moments(p, g.x.back(), std::numeric_limits<double>::infinity());
    pr.n.front() += lo.number;
    pr.n.back() += hi.number;
    pr.below.number += lo.number;
    pr.below.volume += lo.volume;
    pr.above.number += hi.number;
    pr.above.volume += hi.volume;
    for (std::size_t i = 0; i + 1 < m; ++i) {
      const Moments s = population_moments(p, g.x[i], g.x[i + 1]);
      const double up = std::clamp((s.volume - g.x[i] * s.number) / (g.x[i + 1] - g.x[i]), 0.0, s.number);
      pr.n[i + 1] += up;
      pr.n[i] += s.number - up;
    }
  }
  return pr;
}

}  // namespace agglo::sectional
