// Tunable fractal aggregates (structure/fractal.hpp) against the law N = k_f (R_g/abar)^D_f and the
// contact rules (structure/validate.hpp), over seeds and sizes.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "agglo/structure/fractal.hpp"
#include "agglo/structure/primaries.hpp"
#include "agglo/structure/validate.hpp"

namespace agglo::structure {
namespace {

struct Ensemble {
  std::vector<double> n, rg_over_a;
  double worst_law_error = 0.0, worst_contact_error = 0.0;
};

// Builds `seeds` aggregates per size, checks every one (law within 1 %, contacts, overlaps, connected).
Ensemble fractal_ensemble(const std::vector<int>& sizes, int seeds, double sigma_g, int seeds_largest) {
  Ensemble e;
  for (int n : sizes)
    for (int s = 1; s <= (n == sizes.back() ? seeds_largest : seeds); ++s) {
      FractalRequest q{.primaries = n, .fractal_dimension = 1.8, .fractal_prefactor = 1.3, .radius = 1.0,
                       .radius_std = sigma_g, .seed = static_cast<std::uint64_t>(s)};
      const Aggregate a = build_fractal(q);
      EXPECT_EQ(a.size(), static_cast<std::size_t>(n));
      const double abar = geometric_mean(a.r);
      const double law = law_radius_of_gyration(n, 1.3, 1.8, abar);
      const double rg = rg_point_mass(a);
      e.worst_law_error = std::max(e.worst_law_error, std::abs(rg / law - 1.0));
      EXPECT_LT(std::abs(rg / law - 1.0), 0.01) << "N " << n << " seed " << s;
      const Contacts c = validate_structure(a, "test");  // throws on overlap or disconnection
      e.worst_contact_error = std::max(e.worst_contact_error, c.max_error);
      EXPECT_LE(c.max_error, kContactTolerance);
      e.n.push_back(n);
      e.rg_over_a.push_back(rg / abar);
    }
  return e;
}

void expect_fit(const Ensemble& e, const char* label) {
  const FractalFit f = fit_fractal(e.n, e.rg_over_a);
  std::printf("%s: %zu aggregates, fitted D_f = %.4f +- %.4f, k_f = %.4f; worst |R_g/law - 1| = %.2e, worst "
              "contact error = %.2e r\n",
              label, f.points, f.fractal_dimension, f.dimension_stderr, f.fractal_prefactor, e.worst_law_error,
              e.worst_contact_error);
  EXPECT_NEAR(f.fractal_dimension, 1.8, 0.05);
  EXPECT_NEAR(f.fractal_prefactor, 1.3, 0.1);
}

TEST(Fractal, MonodisperseEnsembleFollowsTheLaw) {
  expect_fit(fractal_ensemble({64, 128, 256, 512, 1024}, 10, 1.0, 10), "monodisperse");
}

TEST(Fractal, LognormalEnsembleFollowsTheLawWithGeometricMeanRadius) {
  expect_fit(fractal_ensemble({64, 128, 256, 512, 1024}, 10, 1.5, 10), "lognormal sigma_g = 1.5");
}

TEST(Fractal, SameSeedSameStructureOtherSeedOther) {
  FractalRequest q{.primaries = 100, .radius_std = 1.5, .seed = 7};
  const Aggregate a = build_fractal(q), b = build_fractal(q);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a.x[k].x, b.x[k].x);
    EXPECT_EQ(a.r[k], b.r[k]);
  }
  q.seed = 8;
  const Aggregate c = build_fractal(q);
  EXPECT_NE(a.x[10].x, c.x[10].x);
}

TEST(Fractal, DimensionOutsideTheMethodIsRejectedNamingTheKey) {
  FractalRequest q{.primaries = 64, .fractal_dimension = 1.2};
  try {
    (void)build_fractal(q);
    FAIL() << "D_f = 1.2 accepted";
  } catch (const BuildError& e) {
    EXPECT_EQ(e.key, "fractal_dimension");
  }
}

}  // namespace
}  // namespace agglo::structure
