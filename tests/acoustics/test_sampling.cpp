// Sampling over cells at t = 0 ([sampling], initial_placement.hpp; docs/model.md §C.4): stratified placement
// gives every cell floor(N/C) or ceil(N/C) samples of every population; cloning splits a population
// with too few samples per cell into clones whose integer weights add up to the original weights
// exactly and which carry the original per-particle state, so number, volume, mass and momentum are
// conserved exactly.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "agglo/acoustics/initial_placement.hpp"
#include "helpers.hpp"

using namespace agglo::acoustics;

namespace {

// Two populations (lognormal fines, monodisperse droplets) in a 3-D grid of 20 x 3 x 2 = 120 cells.
std::string two_populations(const std::string& sampling, long fines, long droplets, int seed = 11) {
  return fmt::format(R"(
seed = {}
[sound]
level_db = 140.0
frequency_hz = 2000.0
[domain]
cells_x = 20
cells_y = 3
cells_z = 2
min_cells_per_wavelength = 20
[time]
end = 1e-4
collision_dt = 1e-5
)",
                     seed) +
         test::fines_and_droplets(0.2e-6, 5e11, fines, 20, 30e-6, 1e9, droplets, test::kConserving) +
         "[sampling]\n" + sampling + "\n";
}

// Cell index of every sample, by the engine's binning rule.
std::vector<int> cells_of(const Engine& e) {
  const Domain& D = e.settings().motion.domain;
  const SampleSet& p = e.particles();
  std::vector<int> out(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int cx = std::min(D.cells[0] - 1, static_cast<int>(p.x[i] * (D.cells[0] / D.L[0])));
    const int cy = std::min(D.cells[1] - 1, static_cast<int>(p.y[i] * (D.cells[1] / D.L[1])));
    const int cz = std::min(D.cells[2] - 1, static_cast<int>(p.z[i] * (D.cells[2] / D.L[2])));
    out[i] = (cz * D.cells[1] + cy) * D.cells[0] + cx;
  }
  return out;
}

// Samples per cell of population `pop`.
std::vector<long> per_cell(const Engine& e, int pop) {
  std::vector<long> n(static_cast<std::size_t>(e.settings().motion.domain.num_cells()), 0);
  const std::vector<int> c = cells_of(e);
  for (std::size_t i = 0; i < c.size(); ++i)
    if (e.particles().pop[i] == pop) ++n[static_cast<std::size_t>(c[i])];
  return n;
}

}  // namespace

TEST(Sampling, CloneFactorIsCeilOfMinimumTimesCellsOverSamples) {
  EXPECT_EQ(clone_factor(160, 100, 16), 10);    // the seed baseline's droplets
  EXPECT_EQ(clone_factor(8243, 100, 16), 1);    // its fines
  EXPECT_EQ(clone_factor(200, 100, 16), 8);
  EXPECT_EQ(clone_factor(1599, 100, 16), 2);
  EXPECT_EQ(clone_factor(1600, 100, 16), 1);
  EXPECT_EQ(clone_factor(160, 100, 0), 1);      // the seed's method: never
}

TEST(Sampling, StratifiedPlacementGivesEveryCellFloorOrCeilOfEveryPopulation) {
  for (long droplets : {50L, 120L, 173L, 1000L}) {
    Engine e = test::make_engine(two_populations("min_samples_per_cell = 0", 1234, droplets));
    const long C = 120;
    for (int pop = 0; pop < 2; ++pop) {
      const long N = pop == 0 ? 1234 : droplets;
      const std::vector<long> n = per_cell(e, pop);
      long total = 0, extra = 0;
      for (long k : n) {
        EXPECT_TRUE(k == N / C || k == (N + C - 1) / C) << "population " << pop << ": " << k << " in a cell";
        total += k;
        extra += k > N / C ? 1 : 0;
      }
      EXPECT_EQ(total, N);
      EXPECT_EQ(extra, N % C);
    }
  }
  // The random placement (seed's method) does not: with 173 droplets some cells hold none, others 4 or more.
  Engine r = test::make_engine(two_populations("placement = \"random\"\nmin_samples_per_cell = 0", 1234, 173));
  const std::vector<long> n = per_cell(r, 1);
  EXPECT_GT(*std::max_element(n.begin(), n.end()) - *std::min_element(n.begin(), n.end()), 2);
}

TEST(Sampling, StratifiedExtraCellsAreSeededAndPositionsFillTheCell) {
  Engine a = test::make_engine(two_populations("", 1234, 173, 11));
  Engine b = test::make_engine(two_populations("", 1234, 173, 11));
  Engine c = test::make_engine(two_populations("", 1234, 173, 12));
  EXPECT_EQ(a.particles().x, b.particles().x);  // reproducible
  EXPECT_NE(per_cell(a, 0), per_cell(c, 0));    // another seed, other cells with the extra sample
  // Positions inside the cells: the fractional position along x is uniform (mean 1/2, variance 1/12).
  const Domain& D = a.settings().motion.domain;
  double s = 0.0, s2 = 0.0;
  const std::size_t n = a.particles().size();
  for (std::size_t i = 0; i < n; ++i) {
    const double u = a.particles().x[i] * D.cells[0] / D.L[0];
    const double f = u - std::floor(u);
    s += f;
    s2 += f * f;
  }
  EXPECT_NEAR(s / n, 0.5, 4 * std::sqrt(1.0 / 12 / n));
  EXPECT_NEAR(s2 / n - (s / n) * (s / n), 1.0 / 12, 0.01);
}

TEST(Sampling, CloneSplittingConservesNumberVolumeMassAndMomentumExactly) {
  const Gas g = Gas::air(298.15, 101325.0, true);
  const Sound snd = Sound::make(g, true, 140.0, 2000.0);
  SampleSet p;
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<double> U(0.1, 1.0);
  const std::vector<double> weights = {1, 2, 7, 9, 10, 11, 108, 109, 1001, 123457};
  for (double w : weights) {
    const double vs = U(gen) * 1e-18, vl = U(gen) * 1e-15;
    const std::size_t i = p.add(U(gen), U(gen), U(gen), vs, vl, 1000 * vl + 2500 * vs, w, 1, g, snd);
    p.vx[i] = U(gen) - 0.5;
    p.vy[i] = U(gen) - 0.5;
    p.vz[i] = U(gen) - 0.5;
  }
  const SampleSet before = p;
  const std::size_t n = split_into_clones(p, 0, before.size(), 10);
  ASSERT_EQ(n, p.size());
  ASSERT_EQ(n, 1 + 2 + 7 + 9 + 10 * 6u);  // min(k, w) clones of each sample
  std::size_t i = 0;
  double wsum0 = 0.0, wsum1 = 0.0;
  for (std::size_t m = 0; m < before.size(); ++m) {
    const std::size_t k = static_cast<std::size_t>(std::min(10.0, before.w[m]));
    double w = 0.0, wmin = 1e300, wmax = 0.0;
    for (std::size_t j = 0; j < k; ++j, ++i) {
      // Every clone carries the original's per-particle state bit for bit ...
      for (auto v : {&SampleSet::vol_s, &SampleSet::vol_l, &SampleSet::mass, &SampleSet::vx, &SampleSet::vy,
                            &SampleSet::vz, &SampleSet::d, &SampleSet::tau})
        EXPECT_EQ((p.*v)[i], (before.*v)[m]);
      EXPECT_EQ(p.w[i], std::round(p.w[i]));
      EXPECT_GE(p.w[i], 1.0);
      w += p.w[i];
      wmin = std::min(wmin, p.w[i]);
      wmax = std::max(wmax, p.w[i]);
    }
    // ... and the integer weights of its clones add up to its weight exactly, differing by at most one.
    EXPECT_EQ(w, before.w[m]);
    EXPECT_LE(wmax - wmin, 1.0);
    wsum0 += before.w[m];
    wsum1 += w;
  }
  EXPECT_EQ(wsum1, wsum0);
  // Hence the totals (sum of w times a per-particle quantity) agree to round-off of the summation.
  auto total = [](const SampleSet& s, const std::vector<double>& q) {
    long double t = 0.0L;
    for (std::size_t j = 0; j < s.size(); ++j) t += static_cast<long double>(s.w[j]) * q[j];
    return static_cast<double>(t);
  };
  for (auto v : {&SampleSet::vol_s, &SampleSet::vol_l, &SampleSet::mass})
    EXPECT_NEAR(total(p, p.*v) / total(before, before.*v), 1.0, 1e-15);
  for (auto v : {&SampleSet::vx, &SampleSet::vy, &SampleSet::vz}) {
    std::vector<double> m0(before.size()), m1(p.size());
    for (std::size_t j = 0; j < before.size(); ++j) m0[j] = before.mass[j] * (before.*v)[j];
    for (std::size_t j = 0; j < p.size(); ++j) m1[j] = p.mass[j] * (p.*v)[j];
    EXPECT_NEAR(total(p, m1), total(before, m0), 1e-15 * std::abs(total(before, m0)));
  }
}

TEST(Sampling, CloningInTheEngineReachesTheMinimumPerCellAndKeepsThePopulationNumbers) {
  // 173 droplets in 120 cells with min_samples_per_cell = 16: k = ceil(1920/173) = 12, 2076 clones,
  // every cell 17 or 18; the fines (2500 >= 1920) are not cloned.
  Engine seed_method = test::make_engine(two_populations("placement = \"random\"\nmin_samples_per_cell = 0", 2500, 173));
  Engine e = test::make_engine(two_populations("min_samples_per_cell = 16", 2500, 173));
  ASSERT_EQ(e.sampled().size(), 2u);
  EXPECT_EQ(e.sampled()[0].clone_factor, 1);
  EXPECT_EQ(e.sampled()[0].count, 2500u);
  EXPECT_EQ(e.sampled()[1].clone_factor, 12);
  EXPECT_EQ(e.sampled()[1].count, 173u * 12u);
  EXPECT_EQ(e.sampled()[1].requested, 173u);
  for (long k : per_cell(e, 1)) EXPECT_TRUE(k == 17 || k == 18) << k;
  std::map<int, double> w0, w1;
  for (std::size_t i = 0; i < seed_method.particles().size(); ++i)
    w0[seed_method.particles().pop[i]] += seed_method.particles().w[i];
  for (std::size_t i = 0; i < e.particles().size(); ++i) w1[e.particles().pop[i]] += e.particles().w[i];
  EXPECT_EQ(w1, w0);  // integer weights: the numbers of real particles are identical
  EXPECT_EQ(e.sampled()[1].weight_sum, w1[1]);
}
