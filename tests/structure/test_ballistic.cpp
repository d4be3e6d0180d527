// Ballistic aggregates (structure/ballistic.hpp): contacts and overlaps of every structure, and the
// ensemble fractal dimension against the literature (BPCA ~2.7-3, rising with N; BCCA ~1.9-2.0).
#include <gtest/gtest.h>

#include <cstdio>

#include "agglo/structure/ballistic.hpp"
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
