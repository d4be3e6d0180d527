#pragma once
// Mutual radiation pressure effect (docs/model.md §C.3, eq. 10):
//   beta = P d_i^2 d_j^2 / (d_i + d_j) (d_i F_ij + d_j F_ji)                    [m^3/s]
//   P = sqrt(3) rho_g u_amp^2 / (144 pi mu_g),  F_ij = F_ji = l_i l_j cos(phi_i - phi_j) / r
// rho_g gas density [kg/m^3], mu_g viscosity [Pa s], l slip coefficient, phi = atan(omega tau)
// phase lag, r centre distance floored at contact (F: decision of docs/model.md §C.3).
// d of an aggregate is its collision diameter 2 R_c, its tau that of its mobility diameter (structure.hpp).
// Bound over the cell: l <= 1, cos <= 1, r >= (d_i + d_j)/2 give
//   beta <= 2 P d_i^2 d_j^2 / (d_i + d_j) <= 2 P d_i d_max min(d_i, d_max); over two groups a, b the middle
// form at the largest diameters (it increases with both).
#include <algorithm>
#include <cmath>
#include <string_view>

#include "agglo/acoustics/kernels/cell_bounds.hpp"
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/acoustics/sound.hpp"
#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

// P [1/s].
inline double radiation_pressure_prefactor(const Gas& gas, double u_amp) {
  return std::sqrt(3.0) * gas.density * u_amp * u_amp / (144.0 * constants::pi * gas.viscosity);
}

inline double beta_radiation_pressure(double pref, double r, double di, double dj, double li, double lj,
                                      double cos_dphi) {
  const double s = di + dj;
  r = std::max(r, 0.5 * s);
  const double f = li * lj * cos_dphi / r;
  return pref * di * di * dj * dj / s * (di * f + dj * f);
}

struct RadiationPressure {
  static constexpr std::string_view name = "radiation_pressure";
  double pref;  // P [1/s]

  RadiationPressure(const KernelSettings&, const Gas& gas, const Sound& sound)
      : pref(radiation_pressure_prefactor(gas, sound.u_amp)) {}
  KernelNeeds needs() const { return {.distance = true}; }
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double r) const {
    const double cdphi = p.cphi[i] * p.cphi[j] + p.sphi[i] * p.sphi[j];
    return beta_radiation_pressure(pref, r, p.d[i], p.d[j], p.slip_l[i], p.slip_l[j], cdphi);
  }
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const {
    return 2.0 * pref * p.d[i] * cb.d_max * std::min(p.d[i], cb.d_max);
  }
  double bound_cell(const CellBounds& cb) const { return 2.0 * pref * cb.d_max * cb.d_max * cb.d_max; }
  double bound_pair(const CellBounds& a, const CellBounds& b) const {
    const double s = a.d_max + b.d_max;
    return s > 0.0 ? 2.0 * pref * a.d_max * a.d_max * b.d_max * b.d_max / s : 0.0;
  }
};

}  // namespace agglo::acoustics
