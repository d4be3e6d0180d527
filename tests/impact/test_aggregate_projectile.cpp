// Aggregate-aggregate impacts (projectile.shape, docs/dem.md "Aggregate projectiles"): the projectile
// built by the structure builder is placed with its surface gap_radii r_p before the target and its
// centroid on the flight line; two 8-primary aggregates collide head-on at low speed and stick into
// one, conserving momentum to round-off (no wall, gas or field); the sampled orientations differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <fstream>
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

// A charged aggregate projectile relaxes as the target does (relax_projectile; issue 24 follow-up): the
// same 8-primary chain with alternating charges (+-5e-14 C, about a quarter of the pull-off force
// between neighbours) as target and as projectile. The relaxation moves every projectile primary as it
// moves the target's (same dynamics, translated: equal to 1e-6 of the largest displacement); before,
// the projectile was launched as placed, its contacts out of balance with its charges (and a file's
// charge column alone did not even switch the electrostatics on).
TEST(AggregateProjectile, ChargedProjectileRelaxesAsTheTarget) {
  const std::string csv = testing::TempDir() + "agglo_charged_chain.csv";
  {
    std::ofstream f(csv);
    f << "x,y,z,radius,charge\n";
    for (int k = 0; k < 8; ++k) f << 20e-6 * k << ",0,0,10e-6," << (k % 2 ? -5e-14 : 5e-14) << "\n";
  }
  Config cfg = Config::from_string("[agglomerate]\nshape = \"file\"\nfile = \"" + csv +
                                   "\"\n[projectile]\nshape = \"file\"\nfile = \"" + csv +
                                   "\"\nspeed = 0.05\n[electrostatics]\nsolver = \"coulomb\"\n");
  const ImpactCase c = parse_impact_case(cfg);
  ASSERT_TRUE(c.electrostatics);
  const dem::Particles built = build_agglomerate(c);
  dem::Particles p = relaxed_agglomerate(c);
  const std::size_t n = p.size();
  add_projectile(p, c, 0.05);
  const dem::Particles placed = p;
  relax_projectile(c, p, n, 0.05);
  double moved = 0.0, differ = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 dt = p.x[k] - built.x[k], dp = p.x[n + k] - placed.x[n + k];
    moved = std::max(moved, norm(dt));
    differ = std::max(differ, norm(dp - dt));
    EXPECT_EQ(p.v[n + k].x, 0.05);
  }
  EXPECT_GT(moved, 1e-5 * 10e-6);  // the charges move the primaries by 8e-5 r (equilibrium overlap 6e-3 r)
  EXPECT_LE(differ, 1e-6 * moved) << "projectile and target relax differently: " << differ << " vs " << moved;
}
