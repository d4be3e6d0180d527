// Ballistic aggregates (structure/ballistic.hpp): contacts and overlaps of every structure, and the
// ensemble fractal dimension against the literature (BPCA ~2.7-3, rising with N; BCCA ~1.9-2.0).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "agglo/structure/ballistic.hpp"
#include "agglo/structure/observables.hpp"
#include "agglo/structure/primaries.hpp"
#include "agglo/structure/validate.hpp"

namespace agglo::structure {
namespace {

FractalFit ballistic_fit(Ballistic kind, const std::vector<int>& sizes, int seeds, double sigma_g) {
  std::vector<double> n, rg;
  for (int N : sizes)
    for (int s = 1; s <= seeds; ++s) {
      const Aggregate a = build_ballistic(
          {.kind = kind, .primaries = N, .radius = 1.0, .radius_std = sigma_g, .seed = static_cast<std::uint64_t>(s)});
      EXPECT_EQ(a.size(), static_cast<std::size_t>(N));
      const Contacts c = validate_structure(a, "test");  // throws on overlap or disconnection
      EXPECT_LE(c.max_error, kContactTolerance);
      n.push_back(N);
      rg.push_back(rg_point_mass(a) / geometric_mean(a.r));
    }
  const FractalFit f = fit_fractal(n, rg);
  std::printf("%s N = %d..%d, %d seeds each, sigma_g = %g: D_f = %.3f +- %.3f (standard error), k_f = %.3f\n",
              kind == Ballistic::particle_cluster ? "BPCA" : "BCCA", sizes.front(), sizes.back(), seeds, sigma_g,
              f.fractal_dimension, f.dimension_stderr, f.fractal_prefactor);
  return f;
}

// Literature: 2.73 at N = 256, towards 3 for large N. The band excludes a cluster-cluster value and 3.2+.
TEST(Ballistic, ParticleClusterIsCompact) {
  const FractalFit f = ballistic_fit(Ballistic::particle_cluster, {128, 256, 512}, 40, 1.0);
  EXPECT_GT(f.fractal_dimension, 2.6);
  EXPECT_LT(f.fractal_dimension, 3.1);
  const FractalFit big = ballistic_fit(Ballistic::particle_cluster, {512, 1024}, 10, 1.0);
  EXPECT_GT(big.fractal_dimension, 2.75);  // rising towards 3
}

// The 2.73 quoted for BPCA at N = 256 (Eggersdorfer et al. 2012, J. Aerosol Sci. 46, 7) is not the
// local slope there: agglo reproduces it as the fit of ln R_g,pm on ln N over the growth prefixes
// N = 16, 32, ..., 256 of the aggregates (a prefix of a BPCA aggregate is a BPCA aggregate), while the
// slope between 128 and 256 is ~2.96 (docs/model.md S.3). Pooled least squares over `seeds` aggregates
// of 256 primaries (seeds 1..seeds), prefixes smallest, 2 smallest, ..., 256; sigma by batch means
// over 10 batches of seeds (prefixes of one aggregate are correlated, so not the fit's own error).
struct PooledFit {
  double dimension = 0.0, sigma = 0.0;
};

PooledFit bpca_growth_fit(std::size_t smallest, int seeds) {
  constexpr int kBatches = 10;
  std::vector<std::vector<double>> n(kBatches + 1), rg(kBatches + 1);  // [kBatches] = all seeds
  for (int s = 1; s <= seeds; ++s) {
    const Aggregate a = build_ballistic({.kind = Ballistic::particle_cluster, .primaries = 256, .radius = 1.0,
                                         .seed = static_cast<std::uint64_t>(s)});
    for (std::size_t m = smallest; m <= a.size(); m *= 2) {
      Aggregate prefix;
      prefix.x.assign(a.x.begin(), a.x.begin() + static_cast<std::ptrdiff_t>(m));
      prefix.r.assign(a.r.begin(), a.r.begin() + static_cast<std::ptrdiff_t>(m));
      const double r = rg_point_mass(prefix);
      for (const int b : {s % kBatches, kBatches}) {
        n[static_cast<std::size_t>(b)].push_back(static_cast<double>(m));
        rg[static_cast<std::size_t>(b)].push_back(r);
      }
    }
  }
  PooledFit f;
  f.dimension = fit_fractal(n[kBatches], rg[kBatches]).fractal_dimension;
  double mean = 0.0, sq = 0.0;
  for (int b = 0; b < kBatches; ++b) {
    const double d = fit_fractal(n[static_cast<std::size_t>(b)], rg[static_cast<std::size_t>(b)]).fractal_dimension;
    mean += d, sq += d * d;
  }
  mean /= kBatches;
  f.sigma = std::sqrt((sq / kBatches - mean * mean) * kBatches / (kBatches - 1) / kBatches);
  std::printf("BPCA N = 256, %d seeds, growth prefixes %zu..256: D_f = %.3f +- %.3f (batch means)\n", seeds,
              smallest, f.dimension, f.sigma);
  return f;
}

// 100 seeds: 2.727 +- 0.026 (200 seeds: 2.734 +- 0.015) against 2.73; the negative control, the same
// aggregates' slope between 128 and 256, is 2.955 +- 0.038, > 2.73 by 6 sigma.
TEST(Ballistic, ParticleClusterGrowthFitGivesLiterature273) {
  const PooledFit f = bpca_growth_fit(16, 100);
  EXPECT_LT(f.sigma, 0.04);
  EXPECT_NEAR(f.dimension, 2.73, 3.0 * f.sigma);
  const PooledFit local = bpca_growth_fit(128, 100);
  EXPECT_GT(local.dimension - 2.73, 3.0 * local.sigma);
}

// Literature: 1.9-2.0 (Jullien & Kolb 1984; Meakin).
TEST(Ballistic, ClusterClusterIsOpen) {
  const FractalFit f = ballistic_fit(Ballistic::cluster_cluster, {64, 128, 256, 512, 1024}, 20, 1.0);
  EXPECT_GT(f.fractal_dimension, 1.8);
  EXPECT_LT(f.fractal_dimension, 2.05);
}

TEST(Ballistic, PolydisperseStructuresTouchWithoutOverlap) {
  (void)ballistic_fit(Ballistic::particle_cluster, {64, 256}, 3, 1.5);
  (void)ballistic_fit(Ballistic::cluster_cluster, {64, 256}, 3, 1.5);
}

TEST(Ballistic, SameSeedSameStructure) {
  const BallisticRequest q{.kind = Ballistic::cluster_cluster, .primaries = 37, .radius_std = 1.3, .seed = 5};
  const Aggregate a = build_ballistic(q), b = build_ballistic(q);
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a.x[k].y, b.x[k].y);
}

}  // namespace
}  // namespace agglo::structure
