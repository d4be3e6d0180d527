#pragma once
// Physical constants (SI, CODATA 2018 exact or recommended values).
namespace agglo::constants {
inline constexpr double pi = 3.14159265358979323846;
inline constexpr double eps0 = 8.8541878128e-12;       // vacuum permittivity [F/m]
inline constexpr double k_B = 1.380649e-23;            // Boltzmann constant [J/K]
inline constexpr double R_gas = 8.314462618;           // molar gas constant [J/(mol K)]
inline constexpr double g0 = 9.80665;                  // standard gravity [m/s^2]
}  // namespace agglo::constants
