// PartMC's Brownian kernel (kernels.model = "brownian_partmc") against the values PartMC 2.9.0's own
// routine gives (tests/data/partmc/README.md): every pair to 1e-6 relative, symmetric, and its
// bound a majorant.
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agglo/acoustics/kernels.hpp"
#include "agglo/core/constants.hpp"

using namespace agglo::acoustics;
using agglo::constants::pi;

namespace {

struct KernelRow {
  double d1, d2, k;
};

std::vector<KernelRow> partmc_table() {
  std::ifstream in(std::string(AGGLO_SOURCE_DIR) + "/tests/data/partmc/kernel_brown_298K_101325Pa_rho1000.csv");
  std::vector<KernelRow> rows;
  std::string line;
  std::getline(in, line);  // header d1_m,d2_m,K_m3_per_s
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    KernelRow r{};
    char comma = 0;
    if (ls >> r.d1 >> comma >> r.d2 >> comma >> r.k) rows.push_back(r);
  }
  return rows;
}

}  // namespace

TEST(KernelPartmc, MatchesPartmcTableTo1e6) {
  const auto rows = partmc_table();
  ASSERT_EQ(rows.size(), 45u);  // 45 pairs, (0.2 um, 0.2 um) among them
  const PartmcGas g = PartmcGas::air(298.0, 101325.0);
  for (const auto& r : rows) {
    const double k = beta_brownian_partmc(g, r.d1, r.d2, 1000.0, 1000.0);
    EXPECT_LT(std::abs(k / r.k - 1.0), 1e-6) << "d1 = " << r.d1 << " d2 = " << r.d2 << " K = " << k << " PartMC "
                                             << r.k;
  }
  EXPECT_NEAR(beta_brownian_partmc(g, 0.2e-6, 0.2e-6, 1000.0, 1000.0), 1.04539e-15, 0.00001e-15);
}

TEST(KernelPartmc, Symmetric) {
  const PartmcGas g = PartmcGas::air(298.0, 101325.0);
  for (const auto& r : partmc_table())
    EXPECT_EQ(beta_brownian_partmc(g, r.d1, r.d2, 1000.0, 1500.0), beta_brownian_partmc(g, r.d2, r.d1, 1500.0, 1000.0));
}

TEST(KernelPartmc, MechanismSelectedByNameAndBounded) {
  const Gas gas = Gas::air(298.0, 101325.0, false);
  const Sound snd = Sound::make(gas, false, 140.0, 2000.0);
  KernelSettings ks;
  ks.model = "brownian_partmc";
  EXPECT_EQ(mechanism_names(ks), std::vector<std::string>{"brownian_partmc"});
  const Kernel K(ks, gas, snd);
  ASSERT_TRUE(K.needs_thermal_speed());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  SampleSet p;
  CellBounds cb;
  cb.need_cbar = true;
  for (int i = 0; i < 80; ++i) {
    const double d = 1e-9 * std::pow(1e5, u(rng));  // 1 nm .. 100 um
    const double v = pi * d * d * d / 6;
    cb.include(p, p.add(0, 0, 0, 0, v, 1000.0 * v, 1, 0, gas, snd), gas);
  }
  cb.finalize();
  const PartmcGas pg = PartmcGas::air(298.0, 101325.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_LE(K.bound(p, i, cb), K.bound_cell(cb) * (1 + 1e-12));
    for (std::size_t j = 0; j < p.size(); ++j) {
      const double b = K.beta(p, i, j, 0.0);
      EXPECT_LE(b, K.bound(p, i, cb));
      EXPECT_NEAR(b, beta_brownian_partmc(pg, p.d[i], p.d[j], 1000.0, 1000.0), 1e-9 * b);
    }
  }
}

// The cached form (per-thread factors by sample index) is the direct formula bit for bit: on first use,
// on reuse, after a sample's size and density change (a merge) and under another gas on the same thread.
TEST(KernelPartmc, CachedFactorsGiveTheDirectKernelExactly) {
  const Gas gas = Gas::air(298.0, 101325.0, false);
  const Sound snd = Sound::make(gas, false, 140.0, 2000.0);
  SampleSet p;
  for (int i = 0; i < 6; ++i) {
    const double d = 1e-8 * std::pow(3.0, i), v = pi * d * d * d / 6;
    p.add(0, 0, 0, 0, v, (900.0 + 50.0 * i) * v, 1, 0, gas, snd);
  }
  const auto check_all = [&](const PartmcGas& g) {
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = 0; j < p.size(); ++j)
        EXPECT_EQ(beta_brownian_partmc_cached(g, p, i, j), beta_brownian_partmc(g, p.d[i], p.d[j], p.rho[i], p.rho[j]))
            << i << " " << j;
  };
  const PartmcGas warm = PartmcGas::air(298.0, 101325.0), cold = PartmcGas::air(250.0, 80000.0);
  check_all(warm);
  check_all(warm);  // from the cache
  const double d2 = p.d[2], rho2 = p.rho[2];
  const double v = p.volume(2) + p.volume(4);  // sample 2 takes sample 4 in: new d and rho
  p.vol_l[2] = v;
  p.mass[2] += p.mass[4];
  p.refresh(2, gas, snd);
  ASSERT_NE(p.d[2], d2);
  ASSERT_NE(p.rho[2], rho2);
  check_all(warm);  // sample 2's cached factors are stale and must not be used
  check_all(cold);  // another gas: every entry recomputed
  check_all(warm);
}
