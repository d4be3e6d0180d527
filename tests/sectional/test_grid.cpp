// Pivot grid and initial projection (src/agglo/sectional/grid.hpp, initial.hpp): the split of a particle
// and the projection of a distribution keep number and volume exactly.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "agglo/core/constants.hpp"
#include "agglo/sectional/grid.hpp"
#include "agglo/sectional/initial.hpp"

using namespace agglo::sectional;
using agglo::constants::pi;

TEST(SectionalGrid, GeometricPivots) {
  const Grid g = Grid::geometric(1e-9, 1e-3, 40);
  ASSERT_EQ(g.size(), 241u);
  EXPECT_NEAR(g.d.back(), 1e-3, 1e-15);
  EXPECT_NEAR(g.x[10] / g.x[9], std::pow(10.0, 3.0 / 40.0), 1e-12);
  EXPECT_THROW(Grid::geometric(1e-6, 1e-7, 10), std::invalid_argument);
}

TEST(SectionalGrid, SplitKeepsNumberAndVolume) {
  const Grid g = Grid::geometric(1e-8, 1e-4, 17);
  for (double v : {1.3e-23, 4.1e-20, 7.7e-17, 3.3e-14, g.x[5], 0.999 * g.x.back()}) {
    const Split s = g.split(v);
    ASSERT_EQ(s.hi, s.lo + 1);
    EXPECT_LE(g.x[s.lo], v);
    EXPECT_GT(g.x[s.hi], v);
    EXPECT_NEAR(s.a_lo * g.x[s.lo] + (1 - s.a_lo) * g.x[s.hi], v, 1e-13 * v);
  }
  EXPECT_EQ(g.split(0.5 * g.x.front()).lo, 0u);  // below the grid: whole to the first pivot
  EXPECT_EQ(g.split(2.0 * g.x.back()).hi, g.size() - 1);
  EXPECT_EQ(g.split(2.0 * g.x.back()).a_lo, 1.0);
}

TEST(SectionalGrid, ProjectionKeepsNumberAndVolume) {
  const Grid g = Grid::geometric(1e-9, 1e-3, 20);
  agglo::acoustics::PopulationSpec ex, ln;
  ex.distribution = agglo::acoustics::Distribution::exponential;
  ex.mean_volume = pi / 6 * 8e-15;  // d at mean volume 20 um
  ex.number_concentration = 1e9;
  ln.distribution = agglo::acoustics::Distribution::lognormal;
  ln.geometric_mean_diameter = 0.2e-6;
  ln.geometric_std = 2.0;
  ln.number_concentration = 5e11;
  const double ln_volume = 5e11 * pi / 6 * 8e-21 * std::exp(4.5 * std::log(2.0) * std::log(2.0));
  for (const auto& [p, volume] : {std::pair{ex, 1e9 * ex.mean_volume}, std::pair{ln, ln_volume}}) {
    const Projection pr = project(g, {p});
    double n = 0, v = 0;
    for (std::size_t i = 0; i < g.size(); ++i) {
      EXPECT_GE(pr.n[i], 0.0);
      n += pr.n[i];
      v += pr.n[i] * g.x[i];
    }
    EXPECT_NEAR(n, p.number_concentration, 1e-12 * p.number_concentration);
    EXPECT_NEAR(v, volume, 1e-10 * volume);
    EXPECT_LT(pr.below.number + pr.above.number, 1e-10 * p.number_concentration);
  }
  // Partial moments of the exponential: the whole range gives N and N v0.
  const Moments all = population_moments(ex, 0.0, std::numeric_limits<double>::infinity());
  EXPECT_NEAR(all.number, 1e9, 1e-6);
  EXPECT_NEAR(all.volume, 1e9 * ex.mean_volume, 1e-12 * 1e9 * ex.mean_volume);
}
