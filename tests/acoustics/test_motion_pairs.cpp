// The exact step several samples at a time (Motion::advance_exact_pairs, drag_pairs.cpp: AVX2 four-lane
// and SSE2 two-lane, the step the engine uses) against its reference twin, the one-sample step
// Motion::advance_exact: every bit equal for a population of mixed sizes (fine solids of the seed-002 lognormal, droplets, mixed particles),
// through every branch (cache refills, C_I > 1.001, all three exp branches, wraps), odd counts,
// and after coalescences that change sizes mid-run.
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include <gtest/gtest.h>

#include "agglo/acoustics/drag.hpp"
#include "agglo/acoustics/merge.hpp"
#include "agglo/core/constants.hpp"

using namespace agglo::acoustics;

namespace {

Motion pair_motion(bool sound_on, bool ci, int lanes) {
  Motion m;
  m.max_lanes = lanes;
  m.gas = Gas::air(298.15, 101325.0, true);
  m.sound = Sound::make(m.gas, sound_on, 140.0, 2000.0);
  m.domain.L[0] = m.gas.sound_speed / 2000.0;
  m.domain.L[1] = m.domain.L[2] = 1e-3;  // small: samples cross the y and z faces (wraps)
  m.inertia_correction = ci;
  return m;
}

// n samples: lognormal solids (d_g 0.2 um, sigma_g 2), 30 um droplets, mixed 1-60 um, random
// velocities up to a few times u_amp and random wave-phase caches (empty, near, far).
SampleSet pair_population(const Motion& m, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  SampleSet p;
  const double pi = agglo::constants::pi;
  for (std::size_t k = 0; k < n; ++k) {
    const int kind = static_cast<int>(k % 5);  // 0-2 solids, 3 droplet, 4 mixed
    const double d = kind < 3 ? 0.2e-6 * std::exp(std::log(2.0) * g(rng))
                     : kind == 3 ? 30e-6
                                 : 1e-6 * std::pow(60.0, u(rng));
    const double v = pi * d * d * d / 6;
    const double vs = kind < 3 ? v : kind == 3 ? 0.0 : 0.3 * v, vl = v - vs;
    const std::size_t i = p.add(u(rng) * m.domain.L[0], u(rng) * m.domain.L[1], u(rng) * m.domain.L[2], vs, vl,
                                2500.0 * vs + 1000.0 * vl, std::floor(1.0 + 100.0 * u(rng)), kind == 3 ? 1 : 0,
                                m.gas, m.sound);
    const double scale = std::max(m.sound.u_amp, 0.1);
    p.vx[i] = 3.0 * scale * (2 * u(rng) - 1);
    p.vy[i] = 0.5 * scale * (2 * u(rng) - 1);
    p.vz[i] = -0.2 * scale * u(rng);
    const double kx = m.sound.wavenumber > 0 ? m.sound.wavenumber : 1.0;
    if (k % 3 != 0) {
      p.x_ref[i] = p.x[i] - (k % 3 == 1 ? 0.04 : 0.2) * (2 * u(rng) - 1) / kx;
      p.skx[i] = std::sin(kx * p.x_ref[i]);
      p.ckx[i] = std::cos(kx * p.x_ref[i]);
    }
  }
  return p;
}

::testing::AssertionResult same_state(const SampleSet& a, const SampleSet& b) {
  for (auto f : {&SampleSet::x, &SampleSet::y, &SampleSet::z, &SampleSet::vx, &SampleSet::vy, &SampleSet::vz,
                 &SampleSet::x_ref, &SampleSet::skx, &SampleSet::ckx, &SampleSet::d, &SampleSet::tau})
    for (std::size_t i = 0; i < a.size(); ++i)
      if (std::bit_cast<std::uint64_t>((a.*f)[i]) != std::bit_cast<std::uint64_t>((b.*f)[i]))
        return ::testing::AssertionFailure() << "sample " << i << " (d = " << b.d[i] << "): " << (a.*f)[i]
                                             << " vs reference " << (b.*f)[i];
  return ::testing::AssertionSuccess();
}

}  // namespace

TEST(MotionPairs, EqualsOneSampleReferenceBitForBit) {
  for (int lanes : {4, 2})
  for (bool sound_on : {true, false})
    for (bool ci : {true, false})
      for (double h : {1e-7, 5e-5, 2.5e-3})
        for (std::size_t n : {std::size_t{301}, std::size_t{64}}) {
          const Motion m = pair_motion(sound_on, ci, lanes);
          SampleSet fast = pair_population(m, n, 27 + n);
          SampleSet ref = fast;
          double t = 1.3e-4;
          for (int s = 0; s < 6; ++s, t += h) {
            const Motion::StepTrig tr = m.trig(t, h);
            m.advance_exact_pairs(fast, 1, fast.size(), tr, h);  // an odd start as in the engine's chunks
            for (std::size_t i = 1; i < ref.size(); ++i) m.advance_exact(ref, i, tr, h);
            ASSERT_TRUE(same_state(fast, ref)) << "h = " << h << " step " << s << " sound " << sound_on << " C_I " << ci
                                               << " lanes " << lanes;
          }
        }
}

TEST(MotionPairs, EqualsReferenceAfterMergesChangeSizes) {
  for (int lanes : {4, 2}) {
  const Motion m = pair_motion(true, true, lanes);
  SampleSet fast = pair_population(m, 400, 5);
  std::mt19937_64 rng(9);
  const double h = 5e-5;
  double t = 0.0;
  for (int round = 0; round < 5; ++round) {
    for (int c = 0; c < 40; ++c) {  // coalescences between random pairs: new sizes, densities, weights
      const std::size_t i = rng() % fast.size(), j = rng() % fast.size();
      if (i != j) coalesce_weighted(fast, i, j, m.gas, m.sound);
    }
    SampleSet ref = fast;
    for (int s = 0; s < 4; ++s, t += h) {
      const Motion::StepTrig tr = m.trig(t, h);
      m.advance_exact_pairs(fast, 0, fast.size(), tr, h);
      for (std::size_t i = 0; i < ref.size(); ++i) m.advance_exact(ref, i, tr, h);
      ASSERT_TRUE(same_state(fast, ref)) << "round " << round << " step " << s << " lanes " << lanes;
    }
  }
  }
}
