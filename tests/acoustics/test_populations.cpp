// Initial sampling of populations: integer weights and their total (populations.hpp).
#include <cmath>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "agglo/acoustics/populations.hpp"

using namespace agglo::acoustics;

namespace {
struct Sampled {
  SampledPopulation pop;
  SampleSet p;
};
Sampled sample(Distribution dist, long samples, double conc, bool conserving) {
  const Gas g = Gas::air(298.15, 101325.0, true);
  const Sound snd = Sound::make(g, true, 140.0, 2000.0);
  Domain dom;
  dom.L[0] = snd.wavelength;
  dom.L[1] = dom.L[2] = 0.01;
  dom.cells[0] = 100;
  PopulationSpec s;
  s.name = std::string(1, 't');  // (a literal here trips GCC 12's false -Wrestrict, PR 105329)
  s.phase = Phase::liquid;
  s.distribution = dist;
  s.diameter = 30e-6;
  s.geometric_mean_diameter = 0.2e-6;
  s.geometric_std = 2.0;
  s.number_concentration = conc;
  s.samples = samples;
  s.conserving_rounding = conserving;
  Sampled out;
  out.pop = sample_population(s, 1, dom, 7, g, snd, out.p);
  return out;
}
}  // namespace

TEST(Populations, NearestRoundingCanMissTheTotalConservingRoundingDoesNot) {
  // 1000 cm^-3 of droplets in lambda x 1 cm x 1 cm = 17307.5 droplets on 3200 samples: 5.41 each.
  const Sampled a = sample(Distribution::monodisperse, 3200, 1e9, false);
  EXPECT_NEAR(a.pop.real_number, 17307.5, 1.0);
  EXPECT_EQ(a.pop.weight_sum, 3200.0 * 5.0);  // every weight rounds to 5: -7.5 %
  const Sampled b = sample(Distribution::monodisperse, 3200, 1e9, true);
  EXPECT_LE(std::abs(b.pop.weight_sum - b.pop.real_number), 0.5);
  double wsum = 0.0, wmin = 1e300, wmax = 0.0;
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    EXPECT_EQ(b.p.w[i], std::round(b.p.w[i]));
    wsum += b.p.w[i];
    wmin = std::min(wmin, b.p.w[i]);
    wmax = std::max(wmax, b.p.w[i]);
  }
  EXPECT_EQ(wsum, b.pop.weight_sum);
  EXPECT_EQ(wmin, 5.0);
  EXPECT_EQ(wmax, 6.0);
}

TEST(Populations, ConservingRoundingKeepsTheLognormalTotalAndShape) {
  // Lognormal fines with every sample worth > 1 particle (a sample worth less is given weight 1,
  // with either rounding, which then adds to the total).
  const Sampled a = sample(Distribution::lognormal, 400, 5e10, false);
  const Sampled b = sample(Distribution::lognormal, 400, 5e10, true);
  EXPECT_LE(std::abs(b.pop.weight_sum - b.pop.real_number), 0.5);
  ASSERT_EQ(a.p.size(), b.p.size());
  for (std::size_t i = 0; i < a.p.size(); ++i) {
    EXPECT_EQ(a.p.d[i], b.p.d[i]);
    EXPECT_LE(std::abs(a.p.w[i] - b.p.w[i]), 1.0);  // the two roundings differ by at most one
  }
}

// normal_quantile skips the bisection's evaluations that a checked bracket decides: it must return the
// reference bisection's number bit for bit, in the middle and far into both tails, and be a quantile.
TEST(Populations, FastNormalQuantileIsTheBisectionBitForBit) {
  std::vector<double> qs;
  for (int m = 0; m < 4000; ++m) qs.push_back((m + 0.5) / 4000.0);
  for (double z = -9.0; z <= 9.0; z += 0.0137) qs.push_back(normal_cdf(z));
  for (double q : {1e-300, 1e-200, 1e-20, 0.02425, 0.97575, 0.5, 1.0 - 1e-16}) qs.push_back(q);
  // The stratified quantiles of a lognormal_weights = "equal" population within +-5.5 (cases/partmc_brownian.toml)
  // and a dense grid into the tails, where Phi rounds to few values and the bracket must widen.
  const double Flo = normal_cdf(-5.5), Fhi = normal_cdf(5.5);
  for (int m = 0; m < 20000; ++m) qs.push_back(Flo + (Fhi - Flo) * (m + 0.5) / 20000.0);
  for (double z = -37.0; z <= 8.3; z += 0.0031) qs.push_back(normal_cdf(z));
  for (double q : qs) {
    const double fast = normal_quantile(q), ref = normal_quantile_bisection(q);
    ASSERT_EQ(std::memcmp(&fast, &ref, sizeof fast), 0) << "q = " << q << ": " << fast << " vs " << ref;
  }
  EXPECT_NEAR(normal_quantile(0.975), 1.959963984540054, 1e-13);
  EXPECT_NEAR(normal_quantile(normal_cdf(-5.5)), -5.5, 1e-12);
}
