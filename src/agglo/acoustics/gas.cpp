#include "agglo/acoustics/gas.hpp"

#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

Gas Gas::air(double T, double P, bool gravity_on, std::optional<double> mu_override,
             std::optional<double> lambda_override) {
  using namespace agglo::constants;
  Gas g;
  g.temperature = T;
  g.pressure = P;
  const double M = g.molar_mass;
  g.density = P * M / (R_gas * T);
  g.sound_speed = std::sqrt(1.4 * R_gas * T / M);
  g.viscosity = mu_override ? *mu_override : 1.716e-5 * std::pow(T / 273.15, 1.5) * (273.15 + 110.4) / (T + 110.4);
  g.mean_speed = std::sqrt(8.0 * R_gas * T / (pi * M));
  g.mean_free_path = lambda_override ? *lambda_override : 2.0 * g.viscosity / (g.density * g.mean_speed);
  g.gravity = gravity_on ? g0 : 0.0;
  return g;
}

double Gas::slip_correction(double d) const {
  const double kn = 2.0 * mean_free_path / d;
  return 1.0 + kn * (1.257 + 0.400 * std::exp(-1.100 / kn));
}

double Gas::inertia_correction(double re) { return re > 0.0 ? 1.0 + 0.15 * std::pow(re, 0.687) : 1.0; }


double Gas::relaxation_time(double rho_p, double d) const {
  return rho_p * d * d * slip_correction(d) / (18.0 * viscosity);
}

}  // namespace agglo::acoustics
