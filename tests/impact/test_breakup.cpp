// Break-up probability over an ensemble of impact offsets (breakup.hpp): Wilson interval, the
// crossing speeds, stratified offsets, thread-count independence, and a physical run of the
// neutral tetrahedron far below and far above its v_crit.
#include <gtest/gtest.h>

#include <cmath>
#include <omp.h>

#include "agglo/core/config.hpp"
#include "agglo/impact/breakup.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/run/impact_ensemble.hpp"
#include "agglo/writers/impact.hpp"

using namespace agglo;
using namespace agglo::impact;

TEST(Breakup, WilsonIntervalKnownValues) {
  double lo, hi;
  wilson_interval(0, 16, lo, hi);
  EXPECT_EQ(lo, 0.0);
  EXPECT_NEAR(hi, 0.193613, 1e-6);  // z^2/(n + z^2) = 3.8416/19.8416
  wilson_interval(16, 16, lo, hi);
  EXPECT_NEAR(lo, 1.0 - 0.193613, 1e-6);
  EXPECT_EQ(hi, 1.0);
  wilson_interval(8, 16, lo, hi);  // symmetric about 1/2
  EXPECT_NEAR(lo + hi, 1.0, 1e-12);
  EXPECT_LT(lo, 0.5);
  double lo3, hi3, lo13, hi13;
  wilson_interval(3, 16, lo3, hi3);
  wilson_interval(13, 16, lo13, hi13);
  EXPECT_NEAR(lo3, 1.0 - hi13, 1e-12);
  EXPECT_NEAR(hi3, 1.0 - lo13, 1e-12);
}

TEST(Breakup, FirstCrossingInterpolatesAndReportsNever) {
  std::vector<BreakupPoint> pts(3);
  pts[0].speed = 0.1, pts[0].p = 0.0;
  pts[1].speed = 0.2, pts[1].p = 0.25;
  pts[2].speed = 0.3, pts[2].p = 0.75;
  EXPECT_NEAR(first_crossing(pts, 0.5), 0.25, 1e-12);
  EXPECT_NEAR(first_crossing(pts, 0.1), 0.14, 1e-12);
  EXPECT_EQ(first_crossing(pts, 0.9), -1.0);
  EXPECT_EQ(first_crossing(pts, 0.0), 0.1);
}

// The synthetic impacts as jobs of the ensemble runner on `threads` threads.
ImpactBatch ensemble_of(const std::function<ImpactOutcome(double, double)>& f, int threads) {
  return [f, threads](const std::vector<ImpactJob>& batch) {
    std::vector<agglo::run::Job> jobs;
    for (const auto& b : batch)
      jobs.push_back({"", [f, b](const agglo::run::JobContext&) {
                        return agglo::writers::outcome_json(f(b.speed, b.offset_radii));
                      }});
    std::vector<ImpactOutcome> out;
    for (const auto& o : agglo::run::run_jobs(jobs, {threads})) out.push_back(agglo::writers::outcome_from_json(o.result));
    return out;
  };
}

TEST(Breakup, StratifiedOffsetsAndThreadIndependence) {
  // Synthetic outcome: breaks iff v > 0.1 + offset (offset in r_p), so p(v) is known exactly.
  BreakupSpec spec;
  spec.speeds = {0.3, 0.105, 0.155, 0.205};  // unsorted on purpose; no speed on a tie
  spec.samples = 10;
  spec.offset_spread = 0.1;
  auto run = [](double v, double off) {
    ImpactOutcome o;
    o.speed = v;
    o.contact = true;
    o.broken = v > 0.1 + off;
    return o;
  };
  const BreakupResult a = breakup_probability(spec, 0.05, ensemble_of(run, 1));
  const BreakupResult b = breakup_probability(spec, 0.05, ensemble_of(run, 2));
  ASSERT_EQ(a.offsets.size(), 10u);
  for (int k = 0; k < 10; ++k) EXPECT_NEAR(a.offsets[k], -0.05 + 0.01 + 0.02 * k, 1e-15);  // -0.04 .. 0.14
  ASSERT_EQ(a.points.size(), 4u);
  const double expect_p[4] = {0.3, 0.5, 0.8, 1.0};  // v = 0.105, 0.155, 0.205, 0.3
  for (int s = 0; s < 4; ++s) {
    EXPECT_EQ(a.points[s].runs, 10);
    EXPECT_NEAR(a.points[s].p, expect_p[s], 1e-12) << "v = " << a.points[s].speed;
    EXPECT_EQ(a.points[s].broken, b.points[s].broken);
    EXPECT_LE(a.points[s].ci_lo, a.points[s].p);
    EXPECT_GE(a.points[s].ci_hi, a.points[s].p);
  }
  EXPECT_NEAR(a.v50, 0.155, 1e-12);                          // p reaches 0.5 exactly there
  EXPECT_NEAR(a.v90, 0.205 + 0.095 * (0.9 - 0.8) / 0.2, 1e-12);  // interpolated
  EXPECT_EQ(a.v10, 0.105);                                     // already above 0.1 at the first speed
}

TEST(Breakup, NeutralTetrahedronFarFromThreshold) {
  // v_crit of this case is 0.1775 m/s; 0.12 m/s never breaks and 0.3 m/s always does, whatever the
  // impact offset in 0.05 +- 0.05 r_p.
  Config cfg = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/seed000_neutral_tetrahedron.toml");
  ImpactCase c = parse_impact_case(cfg);
  c.breakup.speeds = {0.12, 0.3};
  c.breakup.samples = 4;
  const auto relaxed = relaxed_agglomerate(c);
  const BreakupResult r =
      breakup_probability(c.breakup, c.projectile.offset_radii, agglo::run::impact_batch(c, relaxed, {2}));
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_EQ(r.points[0].broken, 0);
  EXPECT_EQ(r.points[1].broken, 4);
  for (const auto& o : r.outcomes) EXPECT_TRUE(o.contact);
  EXPECT_GT(r.v50, 0.12);
  EXPECT_LE(r.v50, 0.3);
}
