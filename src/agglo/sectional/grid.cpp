#include "agglo/sectional/grid.hpp"

#include <cmath>
#include <stdexcept>

#include "agglo/core/constants.hpp"

namespace agglo::sectional {

Grid Grid::geometric(double d_min, double d_max, int bins_per_decade) {
  if (!(d_min > 0.0) || !(d_max > d_min) || bins_per_decade < 1)
    throw std::invalid_argument("sectional grid needs 0 < d_min < d_max and bins_per_decade >= 1");
  Grid g;
  const double b = bins_per_decade;
  g.ratio_d = std::pow(10.0, 1.0 / b);
  const auto m = static_cast<std::size_t>(std::ceil(b * std::log10(d_max / d_min) - 1e-9)) + 1;
  for (std::size_t i = 0; i < m; ++i) {
    const double d = d_min * std::pow(10.0, static_cast<double>(i) / b);
    g.d.push_back(d);
    g.x.push_back(constants::pi / 6.0 * d * d * d);
  }
  return g;
}

Split Grid::split(double v) const {
  const std::size_t m = x.size();
  if (v <= x.front()) return {0, 0, 1.0};
  if (v >= x.back()) return {m - 1, m - 1, 1.0};
  // Geometric grid: the index from the logarithm, then corrected for rounding.
  const double r3 = ratio_d * ratio_d * ratio_d;
  auto i = static_cast<std::size_t>(std::log(v / x.front()) / std::log(r3));
  if (i > m - 2) i = m - 2;
  while (i > 0 && x[i] > v) --i;
  while (i + 2 < m && x[i + 1] <= v) ++i;
  return {i, i + 1, (x[i + 1] - v) / (x[i + 1] - x[i])};
}

}  // namespace agglo::sectional
