#pragma once
// Plane travelling sound wave along x (docs/model.md §C.1; Zhao et al. 2023, eqs. 1-2):
//   u_g(x, t) = u_amp sin(omega t - k x),  omega = 2 pi f,  k = omega / c,
//   u_amp = sqrt(2) P_r 10^(L/20) / (c rho_g),  P_r = 2e-5 Pa.
#include "agglo/acoustics/gas.hpp"

namespace agglo::acoustics {

struct Sound {
  bool enabled = true;
  double level_db = 140.0;   // L [dB]
  double frequency = 2000.0; // f [Hz]
  double omega = 0.0;        // [rad/s]
  double wavenumber = 0.0;   // k [1/m]
  double wavelength = 0.0;   // c / f [m]
  double u_amp = 0.0;        // gas velocity amplitude [m/s]

  static Sound make(const Gas& gas, bool enabled, double level_db, double frequency);
  static double amplitude(const Gas& gas, double level_db);  // eq. 2
  double gas_velocity(double x, double t) const;              // eq. 1
};

}  // namespace agglo::acoustics
