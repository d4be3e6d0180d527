#include "agglo/structure/primaries.hpp"

#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::structure {

namespace {

constexpr double kTruncationSigmas = 3.0;

// Standard normal deviate by the Box-Muller transform (one of the pair).
double standard_normal(CounterRng& rng) {
  const double u1 = 1.0 - rng.uniform();  // (0, 1]
  const double u2 = rng.uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * constants::pi * u2);
}

}  // namespace

std::vector<double> primary_radii(int n, double a_g, double sigma_g, CounterRng& rng) {
  std::vector<double> r(static_cast<std::size_t>(n), a_g);
  if (sigma_g <= 1.0) return r;
  const double s = std::log(sigma_g);
  for (auto& x : r) {
    double z = standard_normal(rng);
    while (std::abs(z) > kTruncationSigmas) z = standard_normal(rng);
    x = a_g * std::exp(s * z);
  }
  return r;
}

double geometric_mean(const std::vector<double>& r) {
  double s = 0.0;
  for (double x : r) s += std::log(x);
  return std::exp(s / static_cast<double>(r.size()));
}

}  // namespace agglo::structure
