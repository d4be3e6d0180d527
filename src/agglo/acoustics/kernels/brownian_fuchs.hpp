#pragma once
// Brownian coagulation in the Fuchs transition-regime form (Seinfeld & Pandis, Table 13.1;
// docs/model.md §C.3 option, §C.7.5 check), the kernels.model = "brownian_fuchs" mechanism:
//   beta = 2 pi (D_i + D_j)(d_i + d_j) / [ (d_i + d_j)/(d_i + d_j + 2 g_ij) + 8 (D_i + D_j)/((d_i + d_j) c_ij) ]
//   D = k_B T C_c / (3 pi mu_g d),  c = sqrt(8 k_B T / (pi m)),  l = 8 D / (pi c),
//   g = ((d + l)^3 - (d^2 + l^2)^(3/2)) / (3 d l) - d,  g_ij = sqrt(g_i^2 + g_j^2),  c_ij = sqrt(c_i^2 + c_j^2)
// D diffusivity [m^2/s], c thermal speed [m/s], m particle mass [kg], T gas temperature [K].
// Bound: the denominator exceeds 8 D/(d c), so beta <= (pi/4)(d_i + d_j)^2 c_ij (free-molecular limit).
// Compact spheres only (mass from rho d^3): a case with a fractal population refuses it (compact_spheres_only).
#include <string_view>

#include "agglo/acoustics/kernels/cell_bounds.hpp"
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/acoustics/sound.hpp"

namespace agglo::acoustics {

double thermal_speed(const Gas& gas, double mass);  // sqrt(8 k_B T / (pi m)) [m/s]
double beta_brownian_fuchs(const Gas& gas, double di, double dj, double rhoi, double rhoj);
// Free-molecular bound (pi/4) s^2 sqrt(c_i^2 + c_max^2) with s = d_i + d_max, and its value for a pair
// of the cell's largest samples, (pi/4) (2 d_max)^2 sqrt(2) c_max.
double fuchs_bound(const Gas& gas, const SampleSet& p, std::size_t i, const CellBounds& cb);
double fuchs_bound_cell(const CellBounds& cb);
// Over two groups a, b. The kernel is 1 / (1/beta_c + 1/beta_fm) with beta_c = 2 pi (D_i + D_j)(s + 2 g_ij),
// beta_fm = (pi/4) s^2 c_ij, s = d_i + d_j, increasing in each of D, s, g, c; and g <= l (checked to 1e-6
// over d/l in [1e-6, 1e6]). With the groups' largest D (at their smallest diameter), l <= 8 D_max / (pi c_min)
// (CellBounds::gap_max, set by fuchs_prepare) and c_max, the same expression bounds every pair of a x b.
// speed_scale multiplies the thermal speeds (PartMC's k_B, brownian_partmc.hpp).
double transition_bound_pair(const CellBounds& a, const CellBounds& b, double speed_scale);
// Sets cb.diff_max and cb.gap_max for the Fuchs form from cb.d_min and cb.mass_max.
void fuchs_prepare(const Gas& gas, CellBounds& cb);

struct BrownianFuchs {
  static constexpr std::string_view name = "brownian_fuchs";
  static constexpr bool standalone = true;
  static constexpr bool brownian_term = true;
  static constexpr bool compact_spheres_only = true;
  Gas gas;

  BrownianFuchs(const KernelSettings&, const Gas& g, const Sound&) : gas(g) {}
  KernelNeeds needs() const { return {.thermal_speed = true}; }
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double) const {
    return beta_brownian_fuchs(gas, p.d[i], p.d[j], p.rho[i], p.rho[j]);
  }
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const { return fuchs_bound(gas, p, i, cb); }
  double bound_cell(const CellBounds& cb) const { return fuchs_bound_cell(cb); }
  double bound_pair(const CellBounds& a, const CellBounds& b) const { return transition_bound_pair(a, b, 1.0); }
  void prepare(CellBounds& cb) const { fuchs_prepare(gas, cb); }
};

}  // namespace agglo::acoustics
