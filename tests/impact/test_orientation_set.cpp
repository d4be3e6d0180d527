// The stratified orientation set (orientation_set.hpp) and the orientation-averaged break-up curve
// (breakup.orientations): deterministic proper rotations whose impact directions and rotation
// matrices have the moments of uniform (Haar) rotations; one orientation keeps the jobs, job keys and
// outcomes of before; several orientations give the same outcomes on 1 and 2 threads.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/breakup.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/impact/orientation_set.hpp"
#include "agglo/run/impact_ensemble.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

// Largest deviation of the first and second moments of the rotations from those of uniform
// rotations: E[d] = 0, E[d d^T] = I/3 for the impact directions, E[R] = 0 and
// E[R_ij R_kl] = delta_ik delta_jl / 3 for the matrices.
struct Moments {
  double direction_mean = 0.0, direction_second = 0.0, matrix_mean = 0.0, matrix_second = 0.0;
};

Moments moments(const std::vector<Rotation>& rs) {
  const double n = static_cast<double>(rs.size());
  Moments mo;
  Vec3 mean_d;
  double dd[3][3] = {}, mean_r[3][3] = {}, rr[3][3][3][3] = {};
  for (const auto& r : rs) {
    const Vec3 d{-r.m[0].x, -r.m[0].y, -r.m[0].z};  // R^T (-x): the direction that faces the projectile
    mean_d += d / n;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        dd[i][j] += d[i] * d[j] / n;
        mean_r[i][j] += r.m[i][j] / n;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) rr[i][j][k][l] += r.m[i][j] * r.m[k][l] / n;
      }
  }
  mo.direction_mean = norm(mean_d);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      mo.direction_second = std::max(mo.direction_second, std::abs(dd[i][j] - (i == j ? 1.0 / 3.0 : 0.0)));
      mo.matrix_mean = std::max(mo.matrix_mean, std::abs(mean_r[i][j]));
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          mo.matrix_second =
              std::max(mo.matrix_second, std::abs(rr[i][j][k][l] - (i == k && j == l ? 1.0 / 3.0 : 0.0)));
    }
  return mo;
}

std::vector<Rotation> rotations(int m) {
  std::vector<Rotation> rs;
  for (const auto& o : stratified_orientations(m)) rs.push_back(o.rotation);
  return rs;
}

// Bounds for M = 32 rotations (the set reaches about 0.003, 0.004, 0.045 and 0.063); 32 uniform
// random rotations miss them by far (typical largest deviations about 0.14, 0.08, 0.19 and 0.14).
void expect_even(const Moments& mo, int m) {
  EXPECT_LT(mo.direction_mean, 0.01) << "M = " << m;
  EXPECT_LT(mo.direction_second, 0.01) << "M = " << m;
  EXPECT_LT(mo.matrix_mean, 0.06) << "M = " << m;
  EXPECT_LT(mo.matrix_second, 0.08) << "M = " << m;
}

Config seed_case() { return Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/seed000_neutral_tetrahedron.toml"); }

}  // namespace

TEST(OrientationSet, ProperRotationsFacingTheirDirection) {
  const auto set = stratified_orientations(16);
  ASSERT_EQ(set.size(), 16u);
  for (int k = 0; k < 16; ++k) {
    const auto& o = set[k];
    const Rotation& r = o.rotation;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(dot(r.m[i], r.m[j]), i == j ? 1.0 : 0.0, 1e-14);
    EXPECT_NEAR(dot(r.m[0], cross(r.m[1], r.m[2])), 1.0, 1e-14);  // det = +1: no mirror image
    EXPECT_NEAR(norm(r.apply(o.direction) - Vec3{-1.0, 0.0, 0.0}), 0.0, 1e-14);
    // One direction in each of the 16 equal-area bands of cos(theta).
    EXPECT_GE(o.direction.z, 1.0 - 2.0 * (k + 1) / 16.0);
    EXPECT_LE(o.direction.z, 1.0 - 2.0 * k / 16.0);
    // Deterministic: the same rotation again, bit for bit.
    const auto again = stratified_orientation(k, 16);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(norm2(again.rotation.m[i] - r.m[i]), 0.0);
  }
}

TEST(OrientationSet, CoversOrientationsEvenly) {
  expect_even(moments(rotations(32)), 32);
  // The same bounds reject sets that miss part of SO(3): a fixed roll (the matrix moments), and the
  // directions of one hemisphere only.
  std::vector<Rotation> no_roll, hemisphere;
  const auto set = stratified_orientations(64);
  for (int k = 0; k < 32; ++k) {
    const auto& o = set[2 * k];
    const Vec3 ex{1.0, 0.0, 0.0};
    no_roll.push_back(compose(o.rotation, rotation_about(ex, -o.roll)));
    hemisphere.push_back(set[k].rotation);
  }
  const Moments a = moments(no_roll), b = moments(hemisphere);
  EXPECT_GT(std::max(a.matrix_mean, a.matrix_second), 0.1);
  EXPECT_GT(b.direction_mean, 0.3);
}

TEST(OrientationSet, OneOrientationKeepsJobsAndKeys) {
  BreakupSpec spec;
  spec.speeds = {0.2, 0.1};
  spec.samples = 2;
  spec.offset_spread = 0.05;
  const auto jobs = breakup_jobs(spec, 0.05);
  ASSERT_EQ(jobs.size(), 4u);
  const double v[4] = {0.1, 0.1, 0.2, 0.2}, off[4] = {0.025, 0.075, 0.025, 0.075};
  for (int j = 0; j < 4; ++j) {
    EXPECT_EQ(jobs[j].speed, v[j]);
    EXPECT_NEAR(jobs[j].offset_radii, off[j], 1e-16);
    EXPECT_EQ(jobs[j].orientations, 1);
    EXPECT_EQ(jobs[j].orientation, 0);
  }
  // The key format of before: "v=<speed> offset=<offset>", now in the shortest digits that read back
  // as the same double (issue 23 item 12: "v=0.1", not "v=0.10000000000000001").
  const std::string key = agglo::run::impact_job_key(jobs[1]);
  EXPECT_EQ(key, fmt::format("v={} offset={}", 0.1, jobs[1].offset_radii));
  EXPECT_EQ(std::stod(key.substr(key.find("offset=") + 7)), jobs[1].offset_radii);

  spec.orientations = 3;
  const auto turned = breakup_jobs(spec, 0.05);
  ASSERT_EQ(turned.size(), 12u);  // speed-major, then orientation, offset-minor
  for (int j = 0; j < 12; ++j) {
    EXPECT_EQ(turned[j].speed, v[2 * (j / 6)]);
    EXPECT_EQ(turned[j].orientation, (j / 2) % 3);
    EXPECT_EQ(turned[j].offset_radii, jobs[j % 2].offset_radii);
  }
  EXPECT_EQ(agglo::run::impact_job_key(turned[3]),
            fmt::format("v={} offset={} orientation=1/3", 0.1, turned[3].offset_radii));
}

TEST(OrientationSet, OneOrientationGivesTheOutcomesOfBefore) {
  // One orientation runs each impact from the relaxed agglomerate exactly as run_impact does.
  Config cfg = seed_case();
  ImpactCase c = parse_impact_case(cfg);
  c.breakup.speeds = {0.17, 0.19};
  c.breakup.samples = 2;
  const auto relaxed = relaxed_agglomerate(c);
  const BreakupResult r = breakup_probability(c.breakup, c.projectile.offset_radii, agglo::run::impact_batch(c, relaxed, {2}));
  ASSERT_EQ(r.outcomes.size(), 4u);
  for (std::size_t j = 0; j < 4; ++j) {
    ImpactCase ck = c;
    ck.projectile.offset_radii = r.offsets[j % 2];
    const ImpactOutcome o = run_impact(ck, c.breakup.speeds[j / 2], nullptr, {}, &relaxed);
    EXPECT_EQ(r.outcomes[j].broken, o.broken);
    EXPECT_EQ(r.outcomes[j].steps, o.steps);
    EXPECT_EQ(r.outcomes[j].t_end, o.t_end);
  }
}

TEST(OrientationSet, SeveralOrientationsIndependentOfThreads) {
  Config cfg = seed_case();
  cfg.apply_override("breakup.orientations=4");
  ImpactCase c = parse_impact_case(cfg);
  ASSERT_EQ(c.breakup.orientations, 4);
  c.breakup.speeds = {0.12, 0.3};
  c.breakup.samples = 2;
  const auto relaxed = relaxed_agglomerate(c);
  const BreakupResult a = breakup_probability(c.breakup, c.projectile.offset_radii, agglo::run::impact_batch(c, relaxed, {1}));
  const BreakupResult b = breakup_probability(c.breakup, c.projectile.offset_radii, agglo::run::impact_batch(c, relaxed, {2}));
  ASSERT_EQ(a.outcomes.size(), 16u);
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.points[0].runs, 8);
  for (std::size_t j = 0; j < a.outcomes.size(); ++j) {
    EXPECT_TRUE(a.outcomes[j].contact) << j;  // every orientation is hit: the projectile aims at the centroid
    EXPECT_EQ(a.outcomes[j].broken, b.outcomes[j].broken) << j;
    EXPECT_EQ(a.outcomes[j].steps, b.outcomes[j].steps) << j;
    EXPECT_EQ(a.outcomes[j].t_end, b.outcomes[j].t_end) << j;
  }
  // A rotated relaxed agglomerate keeps its pair distances and centroid; the orientations differ.
  dem::Particles turned = relaxed;
  rotate_about_centroid(turned, stratified_orientation(1, 4).rotation);
  Vec3 c0, c1;
  for (std::size_t k = 0; k < 4; ++k) c0 += relaxed.x[k] / 4.0, c1 += turned.x[k] / 4.0;
  const double r = c.agglomerate.radius;
  EXPECT_LT(norm(c1 - c0), 1e-12 * r);
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      EXPECT_NEAR(norm(turned.x[i] - turned.x[j]), norm(relaxed.x[i] - relaxed.x[j]), 1e-12 * r);
  EXPECT_GT(norm(turned.x[0] - relaxed.x[0]), 0.1 * r);
}
