#pragma once
// Carrier gas (air) properties from temperature and pressure (MODEL C.1; seed 002 section 2.1).
//   rho_g = P M / (R T)                          ideal gas                         [kg/m^3]
//   c     = sqrt(1.4 R T / M)                    speed of sound                    [m/s]
//   mu_g  = 1.716e-5 (T/273.15)^1.5 (273.15+110.4)/(T+110.4)   Sutherland          [Pa s]
//   cbar  = sqrt(8 R T / (pi M))                 mean molecular speed              [m/s]
//   lambda_g = 2 mu_g / (rho_g cbar)             mean free path                    [m]
// Viscosity and mean free path may be overridden (e.g. to compare with textbook tables).
#include <optional>

namespace agglo::acoustics {

struct Gas {
  double temperature = 298.15;   // T [K]
  double pressure = 101325.0;    // P [Pa]
  double molar_mass = 0.0289647; // M [kg/mol]
  double density = 0.0;          // rho_g [kg/m^3]
  double sound_speed = 0.0;      // c [m/s]
  double viscosity = 0.0;        // mu_g [Pa s]
  double mean_speed = 0.0;       // cbar [m/s]
  double mean_free_path = 0.0;   // lambda_g [m]
  double gravity = 0.0;          // |g| [m/s^2], acting along -z; 0 when gravity is off

  static Gas air(double T, double P, bool gravity_on, std::optional<double> mu_override = std::nullopt,
                 std::optional<double> lambda_override = std::nullopt);

  // Cunningham slip correction (seed eq. 5): C_c = 1 + Kn [1.257 + 0.400 exp(-1.100/Kn)], Kn = 2 lambda/d.
  double slip_correction(double d) const;
  // Inertia (Schiller-Naumann) correction (seed eq. 4): C_I = 1 + 0.15 Re^0.687.
  static double inertia_correction(double reynolds);
  // Same with exp(0.687 ln Re) evaluated partly in single precision (relative error of C_I - 1 below
  // 1e-6; used in the motion loop).
  static double inertia_correction_fast(double reynolds);
  // Particle Reynolds number Re = |u - v| d rho_g / mu_g.
  double reynolds(double slip_speed, double d) const { return slip_speed * d * density / viscosity; }
  // Stokes relaxation time with slip, C_I = 1: tau = rho_p d^2 C_c / (18 mu_g) [s].
  double relaxation_time(double rho_p, double d) const;
};

}  // namespace agglo::acoustics
