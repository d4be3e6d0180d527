#pragma once
// Brownian diffusion term of the acoustic kernel sum (docs/model.md §C.3, eq. 11), continuum
// regime with slip:
//   beta = (2 k_B T / (3 mu_g)) (d_i + d_j) (C_c,i / d_i + C_c,j / d_j)          [m^3/s]
// k_B T thermal energy [J], mu_g gas viscosity [Pa s], C_c Cunningham slip correction.
// kernels.brownian_form = "fuchs" takes the Fuchs form of brownian_fuchs.hpp instead.
// Bound over the cell: (2 k_B T / (3 mu_g)) (d_i + d_max)(C_c,i / d_i + max C_c / d); with the Fuchs
// form the larger of that and the free-molecular bound of brownian_fuchs.hpp. Over two groups a, b:
// (2 k_B T / (3 mu_g)) (max_a d + max_b d)(max_a C_c/d + max_b C_c/d), or transition_bound_pair.
#include <algorithm>
#include <string_view>

#include "agglo/acoustics/kernels/brownian_fuchs.hpp"
#include "agglo/acoustics/kernels/cell_bounds.hpp"
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/acoustics/sound.hpp"
#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

// 2 k_B T / (3 mu_g) [m^2/s].
inline double brownian_slip_prefactor(const Gas& gas) {
  return 2.0 * constants::k_B * gas.temperature / (3.0 * gas.viscosity);
}

inline double beta_brownian_slip(const Gas& gas, double di, double dj, double cci, double ccj) {
  return brownian_slip_prefactor(gas) * (di + dj) * (cci / di + ccj / dj);
}

struct Brownian {
  static constexpr std::string_view name = "brownian";
  Gas gas;
  double pref;  // 2 k_B T / (3 mu_g) [m^2/s]
  bool fuchs;   // kernels.brownian_form = "fuchs"

  Brownian(const KernelSettings& s, const Gas& g, const Sound&)
      : gas(g), pref(brownian_slip_prefactor(g)), fuchs(s.brownian_form == BrownianForm::fuchs) {}
  KernelNeeds needs() const { return {.thermal_speed = fuchs}; }
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double) const {
    if (fuchs) return beta_brownian_fuchs(gas, p.d[i], p.d[j], p.rho[i], p.rho[j]);
    return pref * (p.d[i] + p.d[j]) * (p.cc[i] / p.d[i] + p.cc[j] / p.d[j]);
  }
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const {
    const double b = pref * (p.d[i] + cb.d_max) * (p.ccd[i] + cb.ccd_max);
    return fuchs ? std::max(b, fuchs_bound(gas, p, i, cb)) : b;
  }
  double bound_cell(const CellBounds& cb) const {
    const double b = pref * (2.0 * cb.d_max) * 2.0 * cb.ccd_max;
    return fuchs ? std::max(b, fuchs_bound_cell(cb)) : b;
  }
  double bound_pair(const CellBounds& a, const CellBounds& b) const {
    const double s = pref * (a.d_max + b.d_max) * (a.ccd_max + b.ccd_max);
    return fuchs ? transition_bound_pair(a, b, 1.0) : s;
  }
  void prepare(CellBounds& cb) const {
    if (fuchs) fuchs_prepare(gas, cb);
  }
};

}  // namespace agglo::acoustics
