#pragma once
// Brownian coagulation in the free-molecular limit (Seinfeld & Pandis, Table 13.1, Kn >> 1):
//   beta = (pi/4) (d_i + d_j)^2 sqrt(c_i^2 + c_j^2),  c = sqrt(8 k_B T / (pi m))   [m^3/s]
// c mean thermal speed [m/s] of a particle of mass m [kg]. Bounds: d and c are largest for the cell's
// largest diameter and lightest particle (CellBounds::d_max, cbar_max), the free-molecular bounds of
// brownian_fuchs.hpp; over two groups (pi/4) (d_max,a + d_max,b)^2 sqrt(c_max,a^2 + c_max,b^2).
#include <cmath>
#include <string_view>

#include "agglo/acoustics/kernels/brownian_fuchs.hpp"
#include "agglo/acoustics/kernels/cell_bounds.hpp"
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/acoustics/sound.hpp"
#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

struct BrownianFreeMolecular {
  static constexpr std::string_view name = "brownian_free_molecular";
  static constexpr bool standalone = true;     // kernels.model = "brownian_free_molecular"
  static constexpr bool brownian_term = true;  // kernels.brownian = "brownian_free_molecular"
  Gas gas;

  BrownianFreeMolecular(const KernelSettings&, const Gas& g, const Sound&) : gas(g) {}
  KernelNeeds needs() const { return {.thermal_speed = true}; }
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double) const {
    const double s = p.d[i] + p.d[j];
    const double ci = thermal_speed(gas, p.mass[i]), cj = thermal_speed(gas, p.mass[j]);
    return 0.25 * constants::pi * s * s * std::sqrt(ci * ci + cj * cj);
  }
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const { return fuchs_bound(gas, p, i, cb); }
  double bound_cell(const CellBounds& cb) const { return fuchs_bound_cell(cb); }
  double bound_pair(const CellBounds& a, const CellBounds& b) const {
    const double s = a.d_max + b.d_max;
    return 0.25 * constants::pi * s * s * std::sqrt(a.cbar_max * a.cbar_max + b.cbar_max * b.cbar_max);
  }
};

}  // namespace agglo::acoustics
