// Breakage observables (impact/breakage.hpp): hand-built final states with known components and
// contacts, the neutral tetrahedron intact at low speed and damaged at high speed, a sphere that sticks
// to a wall and one that rebounds, their JSON round trip, and the per-speed statistics of breakup.
#include <gtest/gtest.h>

#include <cmath>

#include "agglo/core/config.hpp"
#include "agglo/impact/breakage.hpp"
#include "agglo/impact/breakup.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/writers/impact.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace breakage_test {

// n unit spheres of density 1 on the x axis at x = 2k (a touching chain), at rest.
dem::Particles chain(int n) {
  dem::Particles p;
  for (int k = 0; k < n; ++k) p.add({2.0 * k, 0.0, 0.0}, 1.0, 1.0, {});
  return p;
}

ImpactCase load(const std::string& name) {
  Config cfg = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/" + name);
  return parse_impact_case(cfg);
}

}  // namespace breakage_test

using breakage_test::chain;

TEST(Breakage, TwoPairsFromAChainOfFour) {
  const auto before = chain(4);
  const std::vector<ContactEdge> e0 = {{0, 1}, {1, 2}, {2, 3}};
  auto after = chain(4);
  after.x[2].x += 1.0, after.x[3].x += 1.0;  // 1-2 parted
  const Breakage b = measure_breakage(before, e0, after, {{0, 1}, {2, 3}});
  EXPECT_EQ(b.fragment_sizes, (std::vector<int>{2, 2}));
  EXPECT_EQ(b.size_counts, (std::vector<int>{0, 2}));
  EXPECT_DOUBLE_EQ(b.largest_fraction, 0.5);
  EXPECT_EQ(b.initial_contacts, 3);
  EXPECT_EQ(b.broken_contacts, 1);
  EXPECT_DOUBLE_EQ(b.damage_ratio, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(b.rg_before, std::sqrt(5.0));  // x = 0, 2, 4, 6: (9 + 1 + 1 + 9) / 4
  EXPECT_DOUBLE_EQ(b.rg_after, 1.0);              // the pair 0-1
  EXPECT_DOUBLE_EQ(b.coordination_before, 1.5);
  EXPECT_DOUBLE_EQ(b.coordination_after, 1.0);
  EXPECT_EQ(b.wall, WallOutcome::none);
}

TEST(Breakage, ProjectileJoinsButDoesNotCount) {
  const auto before = chain(3);
  auto after = chain(5);  // particles 3, 4: a projectile (3) and a stray projectile-only component (4)
  // 0-1 parted from 2, the projectile 3 glued to 2; 4 alone holds no primary and is no fragment.
  const Breakage b = measure_breakage(before, {{0, 1}, {1, 2}}, after, {{0, 1}, {2, 3}});
  EXPECT_EQ(b.fragment_sizes, (std::vector<int>{2, 1}));
  EXPECT_EQ(b.size_counts, (std::vector<int>{1, 1}));
  EXPECT_DOUBLE_EQ(b.largest_fraction, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(b.damage_ratio, 0.5);
  // The projectile is not in the graph of the primaries: a whole agglomerate bonded to it is intact.
  const Breakage whole = measure_breakage(before, {{0, 1}, {1, 2}}, after, {{0, 1}, {1, 2}, {2, 3}});
  EXPECT_EQ(whole.fragment_sizes, (std::vector<int>{3}));
  EXPECT_DOUBLE_EQ(whole.damage_ratio, 0.0);
  EXPECT_DOUBLE_EQ(whole.coordination_after, 4.0 / 3.0);
}

TEST(Breakage, ReboundCountsFragmentsOffTheWallMovingAway) {
  auto after = chain(4);
  const Vec3 normal{-1.0, 0.0, 0.0};  // the wall at x > 6, the particles on its -x side
  const std::vector<ContactEdge> edges = {{0, 1}, {2, 3}};
  std::vector<char> on_wall = {0, 0, 0, 1};
  Breakage b;
  measure_rebound(b, after, edges, on_wall, normal, 10.0);  // all at rest: nothing moves away
  EXPECT_EQ(b.wall, WallOutcome::stuck);
  EXPECT_EQ(b.rebound_kinetic, 0.0);
  after.v[0] = {-1.0, 0.0, 0.0}, after.v[1] = {-1.0, 0.5, 0.0};  // the pair 0-1 leaves the wall
  after.v[2] = {-3.0, 0.0, 0.0};  // on the wall with 3 (its pair): not rebounding
  measure_rebound(b, after, edges, on_wall, normal, 10.0);
  const double m = after.m[0];
  EXPECT_EQ(b.wall, WallOutcome::rebounded);
  EXPECT_DOUBLE_EQ(b.rebound_kinetic, 0.5 * m * (1.0 + 1.25));
  EXPECT_DOUBLE_EQ(b.rebound_fraction, b.rebound_kinetic / 10.0);
  after.v[0] = after.v[1] = {1.0, 0.0, 0.0};  // off the wall but moving towards it
  measure_rebound(b, after, edges, on_wall, normal, 10.0);
  EXPECT_EQ(b.wall, WallOutcome::stuck);
  EXPECT_EQ(b.rebound_kinetic, 0.0);
}

TEST(Breakage, TetrahedronIntactAtLowSpeedDamagedAtHighSpeed) {
  // v_crit of this case is 0.1775 m/s (test_breakup.cpp); 0.05 m/s leaves the 6 contacts as they were,
  // 0.12 m/s opens one contact without breaking the agglomerate (restructuring), 0.3 m/s breaks it.
  const ImpactCase c = breakage_test::load("seed000_neutral_tetrahedron.toml");
  const auto relaxed = relaxed_agglomerate(c);
  const ImpactOutcome slow = run_impact(c, 0.05, nullptr, {}, &relaxed);
  const Breakage& s = slow.breakage;
  EXPECT_EQ(s.initial_contacts, 6);
  EXPECT_EQ(s.broken_contacts, 0);
  EXPECT_EQ(s.damage_ratio, 0.0);
  EXPECT_EQ(s.largest_fraction, 1.0);
  EXPECT_EQ(s.fragment_sizes, (std::vector<int>{4}));
  EXPECT_DOUBLE_EQ(s.coordination_before, 3.0);
  EXPECT_DOUBLE_EQ(s.coordination_after, 3.0);
  EXPECT_NEAR(s.rg_after / s.rg_before, 1.0, 1e-6);
  EXPECT_EQ(s.wall, WallOutcome::none);
  const ImpactOutcome opened = run_impact(c, 0.12, nullptr, {}, &relaxed);
  EXPECT_FALSE(opened.broken);
  EXPECT_EQ(opened.breakage.largest_fraction, 1.0);
  EXPECT_GT(opened.breakage.damage_ratio, 0.0);
  EXPECT_LT(opened.breakage.coordination_after, 3.0);
  const ImpactOutcome fast = run_impact(c, 0.3, nullptr, {}, &relaxed);
  const Breakage& f = fast.breakage;
  EXPECT_TRUE(fast.broken);
  EXPECT_GT(f.damage_ratio, 0.0);
  EXPECT_LT(f.largest_fraction, 1.0);
  int total = 0;
  for (int k : f.fragment_sizes) total += k;
  EXPECT_EQ(total, 4);
  const ImpactOutcome back = writers::outcome_from_json(writers::outcome_json(fast));
  EXPECT_EQ(back.breakage.fragment_sizes, f.fragment_sizes);
  EXPECT_EQ(back.breakage.size_counts, f.size_counts);
  EXPECT_EQ(back.breakage.damage_ratio, f.damage_ratio);
  EXPECT_EQ(back.breakage.rg_before, f.rg_before);
}

TEST(Breakage, SphereSticksToWallOrRebounds) {
  // cases/sphere_wall.toml: e = 0.7, sticking velocity 0.0499 m/s against a wall of its own material.
  const ImpactCase c = breakage_test::load("sphere_wall.toml");
  const ImpactOutcome stuck = run_impact(c, 0.04);
  EXPECT_EQ(stuck.breakage.wall, WallOutcome::stuck);
  EXPECT_EQ(stuck.breakage.rebound_kinetic, 0.0);
  EXPECT_EQ(stuck.breakage.rebound_fraction, 0.0);
  const ImpactOutcome off = run_impact(c, 0.07);
  const Breakage& b = off.breakage;
  EXPECT_EQ(b.wall, WallOutcome::rebounded);
  const double m = 4.0 / 3.0 * M_PI * 1e-15 * c.agglomerate.density;
  EXPECT_NEAR(b.impact_kinetic, 0.5 * m * 0.07 * 0.07, 1e-12 * b.impact_kinetic);
  EXPECT_GT(b.rebound_kinetic, 0.0);
  EXPECT_LE(b.rebound_kinetic, b.impact_kinetic);
  EXPECT_LT(b.rebound_fraction, 0.49);  // below e^2: the adhesion takes its share
  const ImpactOutcome back = writers::outcome_from_json(writers::outcome_json(off));
  EXPECT_EQ(back.breakage.wall, WallOutcome::rebounded);
  EXPECT_EQ(back.breakage.rebound_kinetic, b.rebound_kinetic);
}

TEST(Breakage, BreakupAveragesDamageAndLargestFractionPerSpeed) {
  BreakupSpec spec;
  spec.speeds = {1.0, 2.0};
  spec.samples = 2;
  spec.orientations = 2;
  spec.offset_spread = 0.0;
  const ImpactBatch batch = [](const std::vector<ImpactJob>& jobs) {
    std::vector<ImpactOutcome> out;
    for (const auto& j : jobs) {  // damage 0.1 v (1 + orientation), largest 1 - damage
      ImpactOutcome o;
      o.speed = j.speed;
      o.contact = true;
      o.breakage.damage_ratio = 0.1 * j.speed * (1 + j.orientation);
      o.breakage.largest_fraction = 1.0 - o.breakage.damage_ratio;
      out.push_back(o);
    }
    return out;
  };
  const BreakupResult r = breakup_probability(spec, 0.0, batch);
  ASSERT_EQ(r.points.size(), 2u);
  // speed 1: 0.1, 0.1, 0.2, 0.2 -> mean 0.15, s = sqrt(4 x 0.05^2 / (3 x 4)) = 0.05 / sqrt(3)
  EXPECT_NEAR(r.points[0].damage, 0.15, 1e-15);
  EXPECT_NEAR(r.points[0].damage_se, 0.05 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(r.points[0].largest, 0.85, 1e-15);
  EXPECT_NEAR(r.points[0].largest_se, 0.05 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(r.points[1].damage, 0.3, 1e-15);
  EXPECT_NEAR(r.points[1].damage_se, 0.1 / std::sqrt(3.0), 1e-15);
}
