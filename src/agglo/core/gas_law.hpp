#pragma once
// Gas properties and the slip-corrected Stokes drag shared by the DEM (dem/gas_drag.hpp) and the
// acoustic DSMC (acoustics/gas.hpp); docs/model.md §A.6 and §C.1. SI units.
//   mu_g     = 1.716e-5 (T/273.15)^1.5 (273.15 + 110.4)/(T + 110.4)   Sutherland's law for air [Pa s]
//   rho_g    = P M / (R T)                                            ideal gas [kg/m^3]
//   cbar     = sqrt(8 R T / (pi M))                                   mean molecular speed [m/s]
//   lambda_g = 2 mu_g / (rho_g cbar)                                  mean free path [m]
//   C_c      = 1 + Kn [1.257 + 0.400 exp(-1.100/Kn)],  Kn = 2 lambda_g / d   Cunningham slip correction
//   (Zhao et al. 2023, eq. 5, after Davies 1945).
#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::gas {

inline constexpr double kAirMolarMass = 0.0289647;  // M [kg/mol]

inline double sutherland_viscosity(double temperature) {
  return 1.716e-5 * std::pow(temperature / 273.15, 1.5) * (273.15 + 110.4) / (temperature + 110.4);
}

inline double density(double temperature, double pressure, double molar_mass = kAirMolarMass) {
  return pressure * molar_mass / (constants::R_gas * temperature);
}

inline double mean_speed(double temperature, double molar_mass = kAirMolarMass) {
  return std::sqrt(8.0 * constants::R_gas * temperature / (constants::pi * molar_mass));
}

inline double mean_free_path(double viscosity, double density, double mean_speed) {
  return 2.0 * viscosity / (density * mean_speed);
}

// C_c of a sphere of diameter d [m] in a gas of mean free path lambda [m].
inline double cunningham(double d, double lambda) {
  const double kn = 2.0 * lambda / d;
  return 1.0 + kn * (1.257 + 0.400 * std::exp(-1.100 / kn));
}

}  // namespace agglo::gas
