// docs/model.md §C.7.2: single-particle acoustic response (amplitude 1/sqrt(1+(w tau)^2), lag atan(w tau)) and
// settling velocity, for the exact integrator at large steps and the seed's explicit scheme.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "helpers.hpp"

using namespace agglo::acoustics;
using agglo::constants::pi;

namespace {

std::string single_particle_case(double d, double rho, const std::string& integrator, double dt, double motion_dt,
                                 double end, bool sound, bool gravity, bool ci, const std::string& init = "rest") {
  return fmt::format(R"(
seed = 3
[gas]
gravity = {}
[sound]
enabled = {}
level_db = 140.0
frequency_hz = 2000.0
[domain]
{}
cells_x = 1
min_cells_per_wavelength = 1
[time]
end = {}
collision_dt = {}
motion_dt = {}
integrator = "{}"
initial_velocity = "{}"
[[population]]
name = "p"
phase = "liquid"
distribution = "monodisperse"
diameter = {}
number_concentration = 1e6
density = {}
samples = 1
[kernels]
inertia_correction = {}
[output]
psd_times = [0.0]
snapshot_times = [0.0]
)",
                     gravity, sound, sound ? "" : "length_x = 0.01", end, dt, motion_dt, integrator, init, d, rho, ci);
}

struct Fit {
  double amplitude, phase;
};

// Runs until t_start, then projects v_x on sin/cos(w t - k x_mean) over `periods` periods.
Fit fit_response(Engine& e, double t_start, int periods) {
  const auto& s = e.settings().motion.sound;
  while (e.time() < t_start - 1e-12) e.step();
  const double T = 1.0 / s.frequency;
  const double dt = e.settings().collision_dt;
  const int n = static_cast<int>(std::lround(periods * T / dt));
  double a = 0, b = 0, xm = 0;
  std::vector<double> t(n), v(n), x(n);
  for (int k = 0; k < n; ++k) {
    e.step();
    t[k] = e.time();
    v[k] = e.particles().vx[0];
    x[k] = e.particles().x[0];
    xm += x[k] / n;
  }
  for (int k = 0; k < n; ++k) {
    const double psi = s.omega * t[k] - s.wavenumber * xm;
    a += 2.0 / n * v[k] * std::sin(psi);
    b += 2.0 / n * v[k] * std::cos(psi);
  }
  // v = U sin(psi - phi) = U (sin psi cos phi - cos psi sin phi)
  return {std::hypot(a, b) / s.u_amp, std::atan2(-b, a)};
}

}  // namespace

TEST(Motion, AcousticAmplitudeAndPhaseExactIntegratorLargeStep) {
  for (double d : {1e-6, 5e-6, 20e-6}) {
    Engine e = test::make_engine(single_particle_case(d, 1000.0, "exact", 1e-5, 1e-5, 1.0, true, false, false));
    const double tau = e.particles().tau[0], wt = e.settings().motion.sound.omega * tau;
    const Fit f = fit_response(e, std::max(0.003, 30 * tau), 4);
    EXPECT_NEAR(f.amplitude, 1.0 / std::sqrt(1 + wt * wt), 1e-3) << "d = " << d;
    EXPECT_NEAR(f.phase, std::atan(wt), 1e-3) << "d = " << d;
  }
}

TEST(Motion, AcousticAmplitudeAndPhaseExplicitReference) {
  const double d = 5e-6;  // omega tau ~ 1: the most sensitive case
  Engine e = test::make_engine(single_particle_case(d, 1000.0, "explicit", 1e-5, 1e-7, 1.0, true, false, false));
  const double tau = e.particles().tau[0], wt = e.settings().motion.sound.omega * tau;
  const Fit f = fit_response(e, 30 * tau, 3);
  EXPECT_NEAR(f.amplitude, 1.0 / std::sqrt(1 + wt * wt), 3e-3);
  EXPECT_NEAR(f.phase, std::atan(wt), 3e-3);
}

TEST(Motion, SettlingVelocity) {
  for (const char* integ : {"exact", "explicit"}) {
    const double d = 10e-6, rho = 2500.0;
    const double mdt = std::string(integ) == "exact" ? 1e-4 : 1e-6;
    Engine e = test::make_engine(single_particle_case(d, rho, integ, 1e-4, mdt, 1.0, false, true, false));
    const double tau = e.particles().tau[0];
    while (e.time() < 40 * tau) e.step();
    const auto& g = e.settings().motion.gas;
    const double vt = -tau * g.gravity * (rho - g.density) / rho;
    EXPECT_NEAR(e.particles().vz[0] / vt, 1.0, 1e-9) << integ;
    EXPECT_NEAR(e.particles().vx[0], 0.0, 1e-15);
  }
}

TEST(Motion, ExactLargeStepMatchesExplicitReferenceWithInertiaCorrection) {
  // 30 um droplet from rest, full drag law (C_I on), gravity and sound: after 10 ms the exact integrator at
  // dt = 1e-5 s and the seed's explicit scheme at dt = 1e-7 s agree.
  const double d = 30e-6;
  Engine a = test::make_engine(single_particle_case(d, 1000.0, "exact", 1e-5, 1e-5, 1.0, true, true, true));
  Engine b = test::make_engine(single_particle_case(d, 1000.0, "explicit", 1e-5, 1e-7, 1.0, true, true, true));
  double worst = 0.0;
  for (int k = 0; k < 1000; ++k) {
    a.step();
    b.step();
    worst = std::max(worst, std::abs(a.particles().vx[0] - b.particles().vx[0]));
  }
  const double scale = a.settings().motion.sound.u_amp;
  EXPECT_LT(worst / scale, 1e-3);
  EXPECT_NEAR(a.particles().vz[0], b.particles().vz[0], 1e-4 * std::abs(b.particles().vz[0]));
  // Gas displacement amplitude u_amp/omega = 55 um: agreement to 0.2 % of it.
  EXPECT_NEAR(a.particles().x[0], b.particles().x[0], 1e-7);
}

TEST(Motion, NaNStopsTheRunNamingStepAndParticle) {
  Engine e = test::make_engine(single_particle_case(5e-6, 1000.0, "exact", 1e-5, 1e-5, 1.0, true, false, false));
  e.step();
  e.particles().vx[0] = std::nan("");
  try {
    e.step();
    FAIL() << "no NumericalError";
  } catch (const agglo::NumericalError& err) {
    const std::string m = err.what();
    EXPECT_NE(m.find("step 2"), std::string::npos) << m;
    EXPECT_NE(m.find("particle 0"), std::string::npos) << m;
  }
}

namespace {
// Mean x-velocity of the single particle over [0, t_end] (unwrapped displacement / time).
double mean_drift(Engine& e, double t_end) {
  const double L = e.settings().motion.domain.L[0];
  double xu = 0.0, xp = e.particles().x[0];
  while (e.time() < t_end - 1e-12) {
    e.step();
    double dx = e.particles().x[0] - xp;
    dx -= L * std::nearbyint(dx / L);
    xu += dx;
    xp = e.particles().x[0];
  }
  return xu / e.time();
}
}  // namespace

TEST(Motion, StokesDriftOfAFineParticleInTheTravellingWave) {
  // A particle that follows the gas drifts along the wave at the Lagrangian (Stokes) drift
  // u_amp^2 / (2 c) (second order in u_amp). The exact integrator freezes x in the phase over a
  // step and adds the first-order correction in k xi, so the drift is captured at large steps too
  // (without the correction: 0.93 of it at 5e-5 s and 0.75 at 1e-4 s).
  for (double dt : {1e-5, 5e-5, 1e-4, 2.5e-4}) {
    Engine e = test::make_engine(single_particle_case(0.2e-6, 2500.0, "exact", dt, dt, 1.0, true, false, true, "steady"));
    const auto& s = e.settings().motion;
    const double drift = s.sound.u_amp * s.sound.u_amp / (2.0 * s.gas.sound_speed);
    const double r = mean_drift(e, 0.05) / drift;
    std::printf("fine 0.2 um, dt = %g s: drift / (u_amp^2/2c) = %.5f\n", dt, r);
    EXPECT_NEAR(r, 1.0, 0.01) << "dt = " << dt;
  }
}

TEST(Motion, DropletHasNoSpuriousDriftAtLargeSteps) {
  // A 30 um droplet (omega tau ~ 34, C_I up to 1.18) barely follows the wave: its drift is
  // u_amp^2/(2c(1 + (omega tau)^2)) ~ 6e-7 m/s plus the (even) C_I nonlinearity, i.e. ~0. The seed's
  // explicit scheme at 1e-7 s gives -0.9 um/s. Steps with an even number per acoustic period keep
  // the piecewise-constant C_I symmetric; 1e-5 and 5e-5 s must stay within 10 um/s of zero
  // (1.5 % of a fine's drift).
  for (double dt : {1e-5, 5e-5}) {
    Engine e = test::make_engine(single_particle_case(30e-6, 1000.0, "exact", dt, dt, 1.0, true, true, true, "steady"));
    const double u = mean_drift(e, 0.05);
    std::printf("droplet 30 um, dt = %g s: mean x-velocity = %.4g mm/s\n", dt, 1e3 * u);
    EXPECT_NEAR(u, 0.0, 1e-5) << "dt = " << dt;
  }
}

namespace {
// Samples from 0.1 to 60 um (solid and liquid) with random state and every state of the wave-phase
// cache: empty, x_ref close to x (rotation), x_ref far from x (refill).
SampleSet twin_samples(const Motion& m, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  SampleSet p;
  for (std::size_t k = 0; k < n; ++k) {
    const double d = 0.1e-6 * std::pow(600.0, u(rng)), v = pi * d * d * d / 6;
    const bool liquid = k % 3 == 0;
    const std::size_t i = p.add(u(rng) * m.domain.L[0], u(rng) * m.domain.L[1], u(rng) * m.domain.L[2],
                                liquid ? 0.0 : v, liquid ? v : 0.0, (liquid ? 1000.0 : 2500.0) * v, 1.0, 0, m.gas,
                                m.sound);
    const double scale = std::max(m.sound.u_amp, 0.1);
    p.vx[i] = scale * (2 * u(rng) - 1);
    p.vy[i] = 0.1 * scale * (2 * u(rng) - 1);
    p.vz[i] = -0.05 * scale * u(rng);
    const double k_x = m.sound.wavenumber > 0 ? m.sound.wavenumber : 1.0;
    if (k % 4 == 1 || k % 4 == 2) {  // cached at x_ref = x - offset, |k offset| below or above the 0.05 limit
      p.x_ref[i] = p.x[i] - (k % 4 == 1 ? 0.04 : 0.2) * (2 * u(rng) - 1) / k_x;
      p.skx[i] = std::sin(k_x * p.x_ref[i]);
      p.ckx[i] = std::cos(k_x * p.x_ref[i]);
    }
  }
  return p;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b, std::size_t i) {
  return std::bit_cast<std::uint64_t>(a[i]) == std::bit_cast<std::uint64_t>(b[i]);
}
}  // namespace

TEST(Motion, BlockExactStepEqualsOneSampleReferenceBitForBit) {
  // advance_exact_block runs the stages of advance_exact over blocks of 64 samples; every sample must
  // get exactly the reference's result (all bits) for sizes 0.1-60 um, random phases and velocities,
  // steps from 1e-7 to 2.5e-3 s (h / tau_e from ~1e-4 to ~1e5, all three branches of exp), with and
  // without sound and C_I, over consecutive steps (cache refills, wraps).
  for (bool sound_on : {true, false})
    for (bool ci : {true, false}) {
      Motion m;
      m.gas = Gas::air(298.15, 101325.0, true);
      m.sound = Sound::make(m.gas, sound_on, 140.0, 2000.0);
      m.domain.L[0] = 0.1715;
      m.domain.L[1] = m.domain.L[2] = 2e-3;
      m.inertia_correction = ci;
      for (double h : {1e-7, 1e-5, 1e-4, 2.5e-3}) {
        SampleSet block = twin_samples(m, 150, 11);
        SampleSet ref = block;
        double t = 3.1e-4;
        for (int s = 0; s < 3; ++s, t += h) {
          const Motion::StepTrig tr = m.trig(t, h);
          m.advance_exact_block(block, 0, block.size(), tr, h);
          for (std::size_t i = 0; i < ref.size(); ++i) m.advance_exact(ref, i, tr, h);
          for (std::size_t i = 0; i < ref.size(); ++i)
            for (auto f : {&SampleSet::x, &SampleSet::y, &SampleSet::z, &SampleSet::vx, &SampleSet::vy, &SampleSet::vz,
                           &SampleSet::x_ref, &SampleSet::skx, &SampleSet::ckx})
              ASSERT_TRUE(same_bits(block.*f, ref.*f, i))
                  << "sample " << i << " d = " << ref.d[i] << " h = " << h << " step " << s << " sound " << sound_on
                  << " C_I " << ci << ": " << (block.*f)[i] << " vs " << (ref.*f)[i];
        }
      }
    }
}
