// Kernel values (docs/model.md §C.3, C.7.5) and the majorant property the Nanbu guard relies on.
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "agglo/acoustics/kernels.hpp"
#include "agglo/acoustics/kernels/keys.hpp"
#include "agglo/acoustics/nanbu.hpp"
#include "agglo/core/config.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"

using namespace agglo::acoustics;
using agglo::constants::pi;

TEST(Kernels, FuchsValueForTwo200nmSpheres) {
  // Published Fuchs value 1.012e-15 m^3/s (rho = 2000 kg/m^3, 298.15 K, 101325 Pa) is reproduced with the
  // textbook gas values mu = 1.8e-5 Pa s, lambda = 65.1 nm (Seinfeld & Pandis).
  const Gas tb = Gas::air(298.15, 101325.0, false, 1.8e-5, 65.1e-9);
  EXPECT_NEAR(beta_brownian_fuchs(tb, 200e-9, 200e-9, 2000.0, 2000.0), 1.012e-15, 0.002e-15);
  // With the docs/model.md §C.1 gas (mu = 1.837e-5, lambda = 66.5 nm) the same formula gives 1.004e-15 (0.8 % lower).
  const Gas g = Gas::air(298.15, 101325.0, false);
  const double k = beta_brownian_fuchs(g, 200e-9, 200e-9, 2000.0, 2000.0);
  EXPECT_NEAR(k, 1.004e-15, 0.002e-15);
  // Fuchs lies below the continuum+slip form for these sizes and tends to it for large particles.
  EXPECT_LT(k, beta_brownian_slip(g, 200e-9, 200e-9, g.slip_correction(200e-9), g.slip_correction(200e-9)));
  auto ratio = [&](double d) {
    return beta_brownian_fuchs(g, d, d, 2000, 2000) / beta_brownian_slip(g, d, d, g.slip_correction(d), g.slip_correction(d));
  };
  EXPECT_LT(std::abs(1 - ratio(200e-6)), 3e-3);
  EXPECT_LT(std::abs(1 - ratio(200e-6)), 0.5 * std::abs(1 - ratio(20e-6)));
}

TEST(Kernels, MechanismFormulas) {
  const Gas g = Gas::air(298.15, 101325.0, false);
  EXPECT_NEAR(beta_orthokinetic(1e-6, 3e-6, 0.5), pi / 4 * 16e-12 * 0.5, 1e-25);
  // AWE with r floored at contact.
  const double awe_far = beta_acoustic_wake(0.69, 1e-3, 30e-6, 1e-6, 0.99, 0.1);
  EXPECT_NEAR(awe_far, 3.0 / 16 * 0.69 / 1e-3 * 31e-6 * 31e-6 * (30e-6 * 0.99 + 1e-6 * 0.1), 1e-25);
  EXPECT_EQ(beta_acoustic_wake(0.69, 0.0, 30e-6, 1e-6, 0.99, 0.1),
            beta_acoustic_wake(0.69, 15.5e-6, 30e-6, 1e-6, 0.99, 0.1));
  const double kT = agglo::constants::k_B * 298.15;
  EXPECT_NEAR(beta_brownian_slip(g, 1e-6, 2e-6, 1.2, 1.1),
              2 * kT / (3 * g.viscosity) * 3e-6 * (1.2 / 1e-6 + 1.1 / 2e-6), 1e-30);
  // MRPE is ~1e-6 of OI at the seed's conditions (docs/model.md §C.3).
  const double mr = beta_radiation_pressure(radiation_pressure_prefactor(g, 0.69), 1e-3, 30e-6, 1e-6, 0.99, 0.1, 1.0);
  EXPECT_GT(mr, 0.0);
  EXPECT_LT(mr / beta_orthokinetic(30e-6, 1e-6, 0.69), 1e-4);
}

TEST(Kernels, CellBoundIsAMajorant) {
  const Gas gas = Gas::air(298.15, 101325.0, true);
  const Sound snd = Sound::make(gas, true, 140.0, 2000.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (const std::string& m : kernel_model_names()) {
    KernelSettings ks;
    ks.model = m;
    ks.additive_coefficient = 1.0;
    ks.constant_coefficient = 1e-12;
    for (const std::string& brownian : brownian_term_names()) {
      ks.brownian = brownian;
      Kernel K(ks, gas, snd);
      SampleSet p;
      for (int i = 0; i < 60; ++i) {
        const double d = 1e-8 * std::pow(5000.0, u(rng));
        const double v = pi * d * d * d / 6;
        const bool liquid = u(rng) < 0.3;
        const std::size_t k = p.add(u(rng) * 1e-3, u(rng) * 1e-3, u(rng) * 1e-3, liquid ? 0 : v, liquid ? v : 0,
                                    (liquid ? 1000 : 2500) * v, 1 + std::floor(1000 * u(rng)), 0, gas, snd);
        p.vx[k] = u(rng) - 0.5;
        p.vy[k] = 0.1 * (u(rng) - 0.5);
        p.vz[k] = -0.05 * u(rng);
      }
      std::vector<std::uint32_t> idx(p.size());
      for (std::size_t i = 0; i < p.size(); ++i) idx[i] = static_cast<std::uint32_t>(i);
      const CellBounds cb = cell_bounds(p, idx.data(), idx.size(), K, gas);
      const double bc = K.bound_cell(cb);
      for (std::size_t i = 0; i < p.size(); ++i) {
        const double bi = K.bound(p, i, cb);
        EXPECT_LE(bi, bc * (1 + 1e-12));
        for (std::size_t j = 0; j < p.size(); ++j) {
          if (i == j) continue;
          const double r = std::sqrt(std::pow(p.x[i] - p.x[j], 2) + std::pow(p.y[i] - p.y[j], 2) +
                                     std::pow(p.z[i] - p.z[j], 2));
          ASSERT_LE(K.beta(p, i, j, r), bi * (1 + 1e-12)) << "model " << m << " brownian " << brownian << " pair " << i << "," << j;
        }
      }
    }
  }
}

TEST(Kernels, MechanismsAreSelectedByNameInSummationOrder) {
  const Gas gas = Gas::air(298.15, 101325.0, false);
  const Sound snd = Sound::make(gas, true, 140.0, 2000.0);
  KernelSettings ks;
  ks.acoustic_wake = false;
  const Kernel K(ks, gas, snd);
  const std::vector<std::string_view> on = K.mechanisms();
  ASSERT_EQ(on.size(), 3u);
  EXPECT_EQ(on[0], "orthokinetic");
  EXPECT_EQ(on[1], "radiation_pressure");
  EXPECT_EQ(on[2], "brownian");
  EXPECT_TRUE(K.needs_distance());
  EXPECT_FALSE(K.needs_thermal_speed());
  ks.model = "additive";
  const Kernel A(ks, gas, snd);
  ASSERT_EQ(A.mechanisms().size(), 1u);
  EXPECT_EQ(A.mechanisms()[0], "additive");
  EXPECT_TRUE(A.needs_volume());
  EXPECT_FALSE(A.needs_distance());
  ks.model = "acoustic";
  ks.brownian = "brownian_fuchs";  // the Fuchs form as the acoustic sum's Brownian term, in its place
  const Kernel F(ks, gas, snd);
  EXPECT_EQ(F.mechanisms().back(), "brownian_fuchs");
  EXPECT_TRUE(F.needs_thermal_speed());
  // The names each key accepts are those the mechanisms declare.
  EXPECT_EQ(kernel_model_names(),
            (std::vector<std::string>{"acoustic", "brownian_fuchs", "constant", "additive", "brownian_partmc"}));
  EXPECT_EQ(brownian_term_names(), (std::vector<std::string>{"none", "brownian", "brownian_fuchs"}));
  // Every name mechanism_names() can produce is registered, and an unknown one is refused.
  EXPECT_THROW(KernelMechanisms({"orthokinetic", "no_such_mechanism"}, ks, gas, snd), agglo::ConfigError);
}

TEST(Kernels, SumOfMechanismsInOrder) {
  // beta of the acoustic model is the sum of the per-mechanism kernels, added in registry order.
  const Gas gas = Gas::air(298.15, 101325.0, true);
  const Sound snd = Sound::make(gas, true, 140.0, 2000.0);
  SampleSet p;
  const double d0 = 2e-6, d1 = 20e-6, v0 = pi * d0 * d0 * d0 / 6, v1 = pi * d1 * d1 * d1 / 6;
  p.add(1e-4, 0, 0, v0, 0, 2500 * v0, 10, 0, gas, snd);
  p.add(3e-4, 1e-5, 0, 0, v1, 1000 * v1, 1, 1, gas, snd);
  p.vx[0] = 0.3;
  p.vz[1] = -0.01;
  KernelSettings ks;
  ks.collision_efficiency = 0.7;
  const Kernel K(ks, gas, snd);
  const double r = 2.1e-4;
  const double gx = p.vx[0] - p.vx[1], gy = p.vy[0] - p.vy[1], gz = p.vz[0] - p.vz[1];
  double expect = 0.0;
  expect += 0.7 * beta_orthokinetic(p.d[0], p.d[1], std::sqrt(gx * gx + gy * gy + gz * gz));
  expect += beta_acoustic_wake(snd.u_amp, r, p.d[0], p.d[1], p.slip_l[0], p.slip_l[1]);
  expect += beta_radiation_pressure(radiation_pressure_prefactor(gas, snd.u_amp), r, p.d[0], p.d[1], p.slip_l[0],
                                    p.slip_l[1], p.cphi[0] * p.cphi[1] + p.sphi[0] * p.sphi[1]);
  expect += beta_brownian_slip(gas, p.d[0], p.d[1], p.cc[0], p.cc[1]);
  EXPECT_EQ(K.beta(p, 0, 1, r), expect);
}

// [kernels] of a case: names as the mechanisms declare them, the former boolean kernels.brownian, and
// the deprecated kernels.brownian_form ("fuchs" = the brownian_fuchs term) with one warning.
TEST(Kernels, KeysReadNamesAndFormerSpellings) {
  auto read = [](agglo::Config& cfg) { return read_kernels(kernel_keys().t.open(cfg.root())); };
  auto cfg = agglo::Config::from_string("[kernels]\nbrownian = false\n", "case.toml");
  EXPECT_EQ(read(cfg).brownian, "none");
  EXPECT_EQ(mechanism_names(read(cfg)), (std::vector<std::string>{"orthokinetic", "acoustic_wake", "radiation_pressure"}));
  cfg = agglo::Config::from_string("[kernels]\nbrownian_form = \"fuchs\"\n", "case.toml");
  EXPECT_EQ(read(cfg).brownian, "brownian_fuchs");
  const auto warnings = cfg.take_warnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("case.toml: key 'kernels.brownian_form' = \"fuchs\": deprecated"), std::string::npos)
      << warnings[0];
  cfg = agglo::Config::from_string("[kernels]\nbrownian = \"brownian_fuchs\"\n", "case.toml");
  EXPECT_EQ(read(cfg).brownian, "brownian_fuchs");
  EXPECT_TRUE(cfg.take_warnings().empty());
  cfg = agglo::Config::from_string("[kernels]\nmodel = \"orthokinetic\"\n", "case.toml");  // not standalone
  EXPECT_THROW(read(cfg), agglo::ConfigError);
}

// The minimum image's rounding (pair_distance) without libm: the value of std::nearbyint for halves (ties to
// even), near-halves, both signs, large |q| (the libm branch) and random quotients; and the square of the
// image d - L n (what pair_distance uses; -0 may become +0) the same bits as with std::nearbyint.
TEST(Kernels, NearestIntegerIsNearbyint) {
  std::vector<double> qs = {0.0, -0.0, 0.5, 1.5, 2.5, -0.5, -1.5, -2.5, 0.49999999999999994, -0.49999999999999994,
                            0.5000000000000001, 3.4999999999999996, 1e15 + 0.5, -1e15 - 0.5, 0x1p51 + 1.0, 0x1p53,
                            -0x1p60, 1e300};
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int k = 0; k < 10000; ++k) qs.push_back(u(gen));
  for (const double q : qs) {
    const double a = nearest_integer(q), b = std::nearbyint(q);
    EXPECT_EQ(a, b) << q;
    const double L = 0.0123, d = q * L, da = d - L * a, db = d - L * b;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(da * da), std::bit_cast<std::uint64_t>(db * db)) << q;
  }
  EXPECT_TRUE(std::isnan(nearest_integer(std::nan(""))));
}
