#pragma once
// Brownian coagulation exactly as PartMC 2.9.0 computes it (`coag_kernel brown`, after Jacobson 2005,
// eq. 15.33), the kernels.model = "brownian_partmc" mechanism, for like-for-like comparisons with PartMC.
// PartMC's own constants: k_B = 1.3806505e-23 J/K, N_A = 6.02214179e23 1/mol, R = 8.314472 J/(mol K),
// M_air = 2.89644e-2 kg/mol. Gas (T [K], p [Pa] of the case):
//   rho_air = p M_air / (R T),  mu = 1.8325e-5 (416.16/(T + 120)) (T/296.16)^1.5 [Pa s],  nu = mu / rho_air,
//   c_air = sqrt(8 k_B T N_A / (pi M_air)),  lambda = 2 nu / c_air [m].
// Particle of radius r = d/2 [m] and mass m [kg]:
//   Kn = lambda / r,  C_c = 1 + Kn (1.249 + 0.42 exp(-0.87/Kn)),  D = k_B T C_c / (6 pi mu r) [m^2/s],
//   c = sqrt(8 k_B T / (pi m)) [m/s],  l = 8 D / (pi c),  delta = ((2r + l)^3 - (4r^2 + l^2)^1.5) / (6 r l) - 2r.
// Pair:
//   beta = 4 pi (r_i + r_j)(D_i + D_j) / [ (r_i + r_j)/(r_i + r_j + sqrt(delta_i^2 + delta_j^2))
//                                         + 4 (D_i + D_j) / ((r_i + r_j) sqrt(c_i^2 + c_j^2)) ]   [m^3/s]
// Bound: the denominator exceeds its second term, so beta <= pi (r_i + r_j)^2 sqrt(c_i^2 + c_j^2): the
// free-molecular bound of brownian_fuchs.hpp, scaled from agglo's k_B to PartMC's.
// Compact spheres only (mass from rho d^3): a case with a fractal population refuses it (compact_spheres_only).
#include <string_view>

#include "agglo/acoustics/kernels/brownian_fuchs.hpp"
#include "agglo/acoustics/kernels/cell_bounds.hpp"
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/acoustics/sound.hpp"

namespace agglo::acoustics {

// PartMC's gas: temperature [K], viscosity mu [Pa s] and mean free path lambda [m] of the header formulas.
struct PartmcGas {
  double temperature = 0.0, viscosity = 0.0, mean_free_path = 0.0;
  static PartmcGas air(double temperature, double pressure);
};

// beta for spheres of diameters d_i, d_j [m] and densities rho_i, rho_j [kg/m^3].
double beta_brownian_partmc(const PartmcGas& gas, double di, double dj, double rhoi, double rhoj);
// The same for samples i and j of p (d and rho from its caches), bit for bit, with each sample's particle
// factors (r, D, c^2, delta: two pow, one exp, one sqrt) kept per thread and sample index and recomputed
// only when the sample's d or rho (a merge, a split) or the gas changed: the DSMC evaluates a sample
// against many partners between its merges.
double beta_brownian_partmc_cached(const PartmcGas& gas, const SampleSet& p, std::size_t i, std::size_t j);
// sqrt(k_B(PartMC) / k_B(agglo)): turns agglo's thermal speeds into PartMC's.
double partmc_thermal_speed_ratio();
// Sets cb.diff_max (PartMC's D at cb.d_min) and cb.gap_max (8 D_max / (pi c_min), c_min PartMC's thermal speed
// at cb.mass_max) for transition_bound_pair (brownian_fuchs.hpp: the two forms are the same with r = d/2).
void partmc_prepare(const PartmcGas& gas, CellBounds& cb);

struct BrownianPartmc {
  static constexpr std::string_view name = "brownian_partmc";
  static constexpr bool standalone = true;
  static constexpr bool compact_spheres_only = true;
  Gas gas;
  PartmcGas pgas;
  double speed_ratio;

  BrownianPartmc(const KernelSettings&, const Gas& g, const Sound&)
      : gas(g), pgas(PartmcGas::air(g.temperature, g.pressure)), speed_ratio(partmc_thermal_speed_ratio()) {}
  KernelNeeds needs() const { return {.thermal_speed = true}; }
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double) const {
    return beta_brownian_partmc_cached(pgas, p, i, j);
  }
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const {
    return speed_ratio * fuchs_bound(gas, p, i, cb);
  }
  double bound_cell(const CellBounds& cb) const { return speed_ratio * fuchs_bound_cell(cb); }
  double bound_pair(const CellBounds& a, const CellBounds& b) const {
    return transition_bound_pair(a, b, speed_ratio);
  }
  void prepare(CellBounds& cb) const { partmc_prepare(pgas, cb); }
};

}  // namespace agglo::acoustics
