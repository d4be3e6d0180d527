#pragma once
// Brownian diffusion term of the acoustic kernel sum (docs/model.md §C.3, eq. 11), continuum
// regime with slip:
//   beta = (2 k_B T / (3 mu_g)) (d_i + d_j) (C_c,i / d_i + C_c,j / d_j)          [m^3/s]
// k_B T thermal energy [J], mu_g gas viscosity [Pa s], C_c Cunningham slip correction.
// Aggregates (structure.hpp): d_i + d_j are the collision diameters and C_c / d is C_c(d_m) / d_m of the
// mobility diameter (the diffusivity k_B T C_c / (3 pi mu_g d_m)), i.e. 2 pi (D_i + D_j)(d_i + d_j); the
// cache SampleSet::ccd holds it (= C_c / d of a compact sphere, the same division).
// The acoustic sum's default Brownian term (kernels.brownian); the Fuchs form is the mechanism of
// brownian_fuchs.hpp. Bound over the cell: (2 k_B T / (3 mu_g)) (d_i + d_max)(C_c,i / d_i + max C_c / d);
// over two groups a, b: (2 k_B T / (3 mu_g)) (max_a d + max_b d)(max_a C_c/d + max_b C_c/d).
#include <algorithm>
#include <string_view>

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
  static constexpr bool brownian_term = true;
  Gas gas;
  double pref;  // 2 k_B T / (3 mu_g) [m^2/s]

  Brownian(const KernelSettings&, const Gas& g, const Sound&) : gas(g), pref(brownian_slip_prefactor(g)) {}
  KernelNeeds needs() const { return {}; }
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double) const {
    return pref * (p.d[i] + p.d[j]) * (p.ccd[i] + p.ccd[j]);
  }
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const {
    return pref * (p.d[i] + cb.d_max) * (p.ccd[i] + cb.ccd_max);
  }
  double bound_cell(const CellBounds& cb) const { return pref * (2.0 * cb.d_max) * 2.0 * cb.ccd_max; }
  double bound_pair(const CellBounds& a, const CellBounds& b) const {
    return pref * (a.d_max + b.d_max) * (a.ccd_max + b.ccd_max);
  }
};

}  // namespace agglo::acoustics
