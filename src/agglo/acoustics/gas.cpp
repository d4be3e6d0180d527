#include "agglo/acoustics/gas.hpp"

#include <cmath>

#include "agglo/core/constants.hpp"
#include "agglo/core/gas_law.hpp"

namespace agglo::acoustics {

Gas Gas::air(double T, double P, bool gravity_on, std::optional<double> mu_override,
             std::optional<double> lambda_override) {
  using namespace agglo::constants;
  Gas g;
  g.temperature = T;
  g.pressure = P;
  const double M = g.molar_mass;
  g.density = gas::density(T, P, M);
  g.sound_speed = std::sqrt(1.4 * R_gas * T / M);
  g.viscosity = mu_override ? *mu_override : gas::sutherland_viscosity(T);
  g.mean_speed = gas::mean_speed(T, M);
  g.mean_free_path = lambda_override ? *lambda_override : gas::mean_free_path(g.viscosity, g.density, g.mean_speed);
  g.gravity = gravity_on ? g0 : 0.0;
  return g;
}

double Gas::slip_correction(double d) const {
  return gas::cunningham(d, mean_free_path);
}

double Gas::inertia_correction(double re) { return re > 0.0 ? 1.0 + 0.15 * std::pow(re, 0.687) : 1.0; }


double Gas::relaxation_time(double rho_p, double d) const {
  return rho_p * d * d * slip_correction(d) / (18.0 * viscosity);
}

}  // namespace agglo::acoustics
