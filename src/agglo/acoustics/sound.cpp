#include "agglo/acoustics/sound.hpp"

#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

double Sound::amplitude(const Gas& gas, double level_db) {
  constexpr double p_ref = 2e-5;
  return std::sqrt(2.0) * p_ref * std::pow(10.0, level_db / 20.0) / (gas.sound_speed * gas.density);
}

Sound Sound::make(const Gas& gas, bool enabled, double level_db, double frequency) {
  Sound s;
  s.enabled = enabled;
  s.level_db = level_db;
  s.frequency = frequency;
  s.omega = 2.0 * constants::pi * frequency;
  s.wavenumber = s.omega / gas.sound_speed;
  s.wavelength = gas.sound_speed / frequency;
  s.u_amp = enabled ? amplitude(gas, level_db) : 0.0;
  return s;
}

double Sound::gas_velocity(double x, double t) const { return u_amp * std::sin(omega * t - wavenumber * x); }

}  // namespace agglo::acoustics
