// docs/model.md §C.1 reference values of the gas and sound field, and the fast C_I used by the motion loop.
#include <cmath>

#include <gtest/gtest.h>

#include "agglo/acoustics/gas.hpp"
#include "agglo/acoustics/sound.hpp"

using namespace agglo::acoustics;

TEST(Gas, AirAtReferenceConditionsMatchesModelC1) {
  const Gas g = Gas::air(298.15, 101325.0, true);
  EXPECT_NEAR(g.density, 1.1839, 5e-4);
  EXPECT_NEAR(g.sound_speed, 346.15, 0.01);
  EXPECT_NEAR(g.viscosity, 1.837e-5, 0.001e-5);
  // lambda_g = 2 mu_g / (rho_g cbar) evaluates to 66.48 nm (an earlier version of the specification quoted "~66.6 nm").
  EXPECT_NEAR(g.mean_free_path, 2 * g.viscosity / (g.density * g.mean_speed), 1e-20);
  EXPECT_NEAR(g.mean_free_path, 66.6e-9, 0.2e-9);
  EXPECT_NEAR(g.gravity, 9.80665, 1e-12);
  EXPECT_EQ(Gas::air(298.15, 101325.0, false).gravity, 0.0);
}

TEST(Sound, AmplitudeAt140dB) {
  const Gas g = Gas::air(298.15, 101325.0, true);
  const Sound s = Sound::make(g, true, 140.0, 2000.0);
  EXPECT_NEAR(s.u_amp, 0.690, 5e-4);
  EXPECT_NEAR(s.wavelength, 346.15 / 2000.0, 1e-5);
  EXPECT_NEAR(s.gas_velocity(0.0, 0.25 / 2000.0), s.u_amp, 1e-12);
  // +20 dB = x10 amplitude.
  EXPECT_NEAR(Sound::amplitude(g, 160.0) / Sound::amplitude(g, 140.0), 10.0, 1e-12);
}

TEST(Gas, SlipCorrectionLimits) {
  const Gas g = Gas::air(298.15, 101325.0, true);
  const double kc = 2 * g.mean_free_path / 1e-3;  // continuum: 1 + 1.257 Kn
  EXPECT_NEAR(g.slip_correction(1e-3), 1.0 + 1.257 * kc, 1e-12);
  const double d = 1e-9, kn = 2 * g.mean_free_path / d;  // free molecular: -> 1 + 1.657 Kn
  EXPECT_NEAR(g.slip_correction(d) / (1 + kn * 1.657), 1.0, 3e-3);
  EXPECT_NEAR(g.slip_correction(0.2e-6), 1.0 + (2 * g.mean_free_path / 0.2e-6) *
                                                   (1.257 + 0.4 * std::exp(-1.1 / (2 * g.mean_free_path / 0.2e-6))),
              1e-14);
}

TEST(Gas, FastInertiaCorrectionMatchesPow) {
  double worst = 0.0;
  for (double re = 1e-10; re < 1e4; re *= 1.01) {
    const double a = Gas::inertia_correction_fast(re) - 1.0, b = Gas::inertia_correction(re) - 1.0;
    worst = std::max(worst, std::abs(a / b - 1.0));
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(Gas::inertia_correction_fast(0.0), 1.0);
}
