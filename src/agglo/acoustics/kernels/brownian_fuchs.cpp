#include "agglo/acoustics/kernels/brownian_fuchs.hpp"

#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

using constants::k_B;
using constants::pi;

double thermal_speed(const Gas& gas, double mass) { return std::sqrt(8.0 * k_B * gas.temperature / (pi * mass)); }

namespace {
struct FuchsSample {
  double D, c, g;  // diffusivity, thermal speed, g of the header formula
};
FuchsSample fuchs_sample(const Gas& gas, double d, double rho) {
  FuchsSample s;
  s.D = k_B * gas.temperature * gas.slip_correction(d) / (3.0 * pi * gas.viscosity * d);
  s.c = thermal_speed(gas, rho * pi * d * d * d / 6.0);
  const double l = 8.0 * s.D / (pi * s.c);
  s.g = (std::pow(d + l, 3) - std::pow(d * d + l * l, 1.5)) / (3.0 * d * l) - d;
  return s;
}
}  // namespace

double beta_brownian_fuchs(const Gas& gas, double di, double dj, double rhoi, double rhoj) {
  const FuchsSample a = fuchs_sample(gas, di, rhoi), b = fuchs_sample(gas, dj, rhoj);
  const double ds = di + dj, Ds = a.D + b.D;
  const double gs = std::sqrt(a.g * a.g + b.g * b.g), cs = std::sqrt(a.c * a.c + b.c * b.c);
  return 2.0 * pi * Ds * ds / (ds / (ds + 2.0 * gs) + 8.0 * Ds / (ds * cs));
}

double fuchs_bound(const Gas& gas, const SampleSet& p, std::size_t i, const CellBounds& cb) {
  const double sd = p.d[i] + cb.d_max;
  const double ci = thermal_speed(gas, p.mass[i]);
  return 0.25 * pi * sd * sd * std::sqrt(ci * ci + cb.cbar_max * cb.cbar_max);
}

double fuchs_bound_cell(const CellBounds& cb) {
  const double sd = 2.0 * cb.d_max;
  return 0.25 * pi * sd * sd * std::sqrt(2.0) * cb.cbar_max;
}

double transition_bound_pair(const CellBounds& a, const CellBounds& b, double speed_scale) {
  const double s = a.d_max + b.d_max;
  const double c = speed_scale * std::sqrt(a.cbar_max * a.cbar_max + b.cbar_max * b.cbar_max);
  const double beta_fm = 0.25 * pi * s * s * c;
  const double beta_c = 2.0 * pi * (a.diff_max + b.diff_max) * (s + 2.0 * std::sqrt(a.gap_max * a.gap_max + b.gap_max * b.gap_max));
  return beta_c + beta_fm > 0.0 ? beta_c * beta_fm / (beta_c + beta_fm) : 0.0;
}

void fuchs_prepare(const Gas& gas, CellBounds& cb) {
  if (!(cb.d_min > 0.0 && cb.mass_max > 0.0)) return;
  cb.diff_max = k_B * gas.temperature * gas.slip_correction(cb.d_min) / (3.0 * pi * gas.viscosity * cb.d_min);
  cb.gap_max = 8.0 * cb.diff_max / (pi * thermal_speed(gas, cb.mass_max));
}

}  // namespace agglo::acoustics
