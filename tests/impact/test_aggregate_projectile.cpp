// Aggregate-aggregate impacts (projectile.shape, docs/dem.md "Aggregate projectiles"): the projectile
// built by the structure builder is placed with its surface gap_radii r_p before the target and its
// centroid on the flight line; two 8-primary aggregates collide head-on at low speed and stick into
// one, conserving momentum to round-off (no wall, gas or field); the sampled orientations differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "agglo/core/config.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/impact/impact_run.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

ImpactCase aggregate_case() {
  Config cfg = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/aggregate_aggregate.toml");
  return parse_impact_case(cfg);
}

Vec3 momentum(const dem::Particles& p) {
  Vec3 P;
  for (std::size_t q = 0; q < p.size(); ++q) P += p.m[q] * p.v[q];
  return P;
}

}  // namespace

TEST(AggregateProjectile, PlacedBeforeTheTarget) {
  const ImpactCase c = aggregate_case();
  ASSERT_EQ(c.projectile.shape, "bpca");
  dem::Particles p = build_agglomerate(c);
  const std::size_t n_agg = p.size();
  add_projectile(p, c, 0.05);
  ASSERT_EQ(n_agg, 8u);
  ASSERT_EQ(p.size(), 16u);
  double target_front = 1e300, projectile_back = -1e300;
  Vec3 ct, cp;
  for (std::size_t q = 0; q < p.size(); ++q) {
    if (q < n_agg) {
      target_front = std::min(target_front, p.x[q].x - p.r[q]);
      ct += p.x[q] / 8.0;
    } else {
      projectile_back = std::max(projectile_back, p.x[q].x + p.r[q]);
      cp += p.x[q] / 8.0;
      EXPECT_EQ(p.v[q].x, 0.05);
    }
  }
  EXPECT_NEAR(target_front - projectile_back, 0.5 * 10e-6, 1e-15);
  EXPECT_NEAR(cp.y, ct.y, 1e-15);  // offset_radii = 0: head-on
  EXPECT_NEAR(cp.z, ct.z, 1e-15);
}

TEST(AggregateProjectile, HeadOnStickAndConserveMomentum) {
  const ImpactCase c = aggregate_case();
  ImpactRun run(c, build_agglomerate(c), 0.05, nullptr);
  const Vec3 p0 = momentum(run.state().dem.particles);
  const ImpactOutcome o = run.run();
  ASSERT_TRUE(o.contact);
  EXPECT_FALSE(o.broken);
  ASSERT_EQ(o.components.size(), 1u);  // one aggregate of 16 primaries
  EXPECT_EQ(o.components.front().size(), 16u);
  EXPECT_EQ(o.breakage.damage_ratio, 0.0);
  const dem::Particles& end = run.state().dem.particles;
  const Vec3 p1 = momentum(end);
  EXPECT_GT(p0.x, 0.0);
  EXPECT_LT(norm(p1 - p0), 1e-12 * norm(p0)) << "momentum before " << p0.x << " after " << p1.x;
  // Stuck: every particle moves with the centre of mass (to the rattle of the contacts).
  const double mtot = std::accumulate(end.m.begin(), end.m.end(), 0.0);
  EXPECT_NEAR(p1.x / mtot, 0.025, 1e-12);  // equal masses: half the launch speed
}

TEST(AggregateProjectile, OrientationsOfTheProjectileDiffer) {
  const ImpactCase c = aggregate_case();
  const Rotation a = projectile_orientation(c, 0), b = projectile_orientation(c, 1);
  double diff = 0.0;
  for (int i = 0; i < 3; ++i) diff += norm(a.m[i] - b.m[i]);
  EXPECT_GT(diff, 1e-3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(norm(a.m[i]), 1.0, 1e-12);  // a rotation
  // projectile.orientation = "random" is orientation 0.
  for (int i = 0; i < 3; ++i) EXPECT_EQ(norm(c.projectile.rotation.m[i] - a.m[i]), 0.0);
}
