// agglo outcomes' grid (impact/outcome_grid.hpp, docs/outcomes.md): the head-on sphere-sphere table of the
// seed material puts its 50 % sticking speed at the closed-form JKR value, the sampled impact parameters,
// the symmetric tabulation and the Wilson interval.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "agglo/core/config.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/dem/jkr.hpp"
#include "agglo/impact/outcome_grid.hpp"
#include "outcome_case_helpers.hpp"
#include "sphere_grid_helpers.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

// Two spheres of the seed material (r = 10 um, e = 0.7), no friction, damping as given, the contact resolved by 800
// steps per period (as the sphere-wall sticking test, tests/impact/test_vcrit_sticking.cpp).
std::string pair_case(const std::string& grid, const std::string& damping = "damping = \"none\"") {
  return test::seed_material("0.0") + R"([contact]
)" + damping + R"(
[agglomerate]
shape = "list"
[[particles]]
position = [0.0, 0.0, 0.0]
radius = 10e-6
[time]
steps_per_period = 800
after_contact = 1e-4
[outcome_grid]
)" + grid;
}

using Parsed = test::SphereGrid;
Parsed parse_pair(const std::string& grid, const std::string& damping = "damping = \"none\"") {
  return test::parse_sphere_grid(pair_case(grid, damping));
}

OutcomeGridResult run_grid(const Parsed& p) { return test::run_sphere_grid(p); }

// Head-on (max_offset = 0) equal spheres at speeds 0.875-1.125 v in steps of 5 % around the expected
// sticking speed v (none at v itself, where the discrete outcome is not monotonic within 0.1 %,
// docs/dem.md): the table sticks (P = 1) below v and bounces (P = 0) above it, so its 50 % speed, between
// the last node that sticks and the first that bounces, brackets v within one grid step.
void expect_fifty_percent_speed(double v, const std::string& damping) {
  std::vector<double> speeds;
  for (int k = -3; k <= 2; ++k) speeds.push_back(v * (1.0 + 0.05 * (k + 0.5)));
  const Parsed p = parse_pair(
      fmt::format("speeds = [{}]\ndiameters = [20e-6]\nimpacts = 1\nmax_offset = 0.0\n", fmt::join(speeds, ", ")),
      damping);
  const OutcomeGridResult t = run_grid(p);
  double last_stick = 0.0, first_bounce = 1e300;
  for (std::size_t iv = 0; iv < speeds.size(); ++iv) {
    const std::size_t i = t.index(iv, 0, 0);
    ASSERT_EQ(t.impacts[i], 1);
    EXPECT_EQ(t.sticks[i] == 1, speeds[iv] < v) << "v_n = " << speeds[iv] << " m/s, expected v_s = " << v;
    if (t.sticks[i] == 1) last_stick = std::max(last_stick, speeds[iv]);
    else first_bounce = std::min(first_bounce, speeds[iv]);
  }
  std::printf("expected v_s = %.6g m/s; the table sticks up to %.6g and bounces from %.6g m/s\n", v, last_stick,
              first_bounce);
  EXPECT_LT(last_stick, v);
  EXPECT_GT(first_bounce, v);
  EXPECT_LT(first_bounce / last_stick, 1.06);  // the 50 % speed within one grid step
}

// Closed form of equal spheres (r = 10 um, seed material): v_s = 1.3678 sqrt(F_C delta_C / m*) with
// R* = r/2, m* = m/2, 1/E* = 2 (1 - nu^2)/E (docs/model.md §A.4 item 5: 0.02239 m/s).
double pair_sticking_speed() {
  const double r = 10e-6, m = 4.0 / 3.0 * constants::pi * r * r * r * 2500.0;
  const auto jkr = dem::JkrPair::make(0.5 * r, 1e9 / (2.0 * (1.0 - 0.33 * 0.33)), 0.01);
  return 1.3678 * std::sqrt(jkr.Fc * jkr.deltaC / (0.5 * m));
}

}  // namespace

TEST(OutcomeGrid, HeadOnFiftyPercentSpeedIsTheJkrSticking) {
  expect_fifty_percent_speed(pair_sticking_speed(), "damping = \"none\"");
}

// With the alpha(e) damping at e = 0.7 the sticking speed is g(0.7) = 1.983 times the undamped one
// (docs/model.md §A.4 item 6).
TEST(OutcomeGrid, DampedFiftyPercentSpeedIsGTimesTheJkrSticking) {
  expect_fifty_percent_speed(1.983 * pair_sticking_speed(), "damping = \"alpha\"");
}

TEST(OutcomeGrid, ImpactParametersAndSymmetricTable) {
  const Parsed p = parse_pair("speeds = [0.1, 0.2]\ndiameters = [1e-6, 2e-6, 4e-6]\nimpacts = 400\nmax_offset = 0.6\n");
  const auto jobs = outcome_impacts(p.grid);
  ASSERT_EQ(jobs.size(), 2u * 6u * 400u);  // nodes with d_1 <= d_2 only
  EXPECT_EQ(jobs, outcome_impacts(p.grid));
  // b^2 / (f (r_1 + r_2))^2 is uniform on [0, 1): mean 1/2, variance 1/12 (400 x 12 samples).
  double s = 0, s2 = 0;
  for (const auto& j : jobs) {
    ASSERT_GE(j.b_fraction, 0.0);
    ASSERT_LT(j.b_fraction, 0.6);
    const double u = j.b_fraction * j.b_fraction / 0.36;
    s += u;
    s2 += u * u;
  }
  const double n = static_cast<double>(jobs.size()), mean = s / n;
  EXPECT_NEAR(mean, 0.5, 3.0 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NEAR(s2 / n - mean * mean, 1.0 / 12.0, 0.01);
  // Radii and offset of one impact: the target takes d_1, the projectile d_2, offset b in units of r_1;
  // the launch speed gives the grid's normal speed at contact.
  const OutcomeImpact& j = jobs[400 * 1 + 7];  // speed 0, (d_1, d_2) = (1, 2) um, sample 7
  ASSERT_EQ(j.i1, 0u);
  ASSERT_EQ(j.i2, 1u);
  const ImpactCase c = outcome_case(p.dem, p.grid, j);
  EXPECT_DOUBLE_EQ(c.agglomerate.particles[0].radius, 0.5e-6);
  EXPECT_DOUBLE_EQ(c.projectile.radius, 1e-6);
  EXPECT_DOUBLE_EQ(c.projectile.offset_radii * 0.5e-6, j.b_fraction * 1.5e-6);
  EXPECT_DOUBLE_EQ(outcome_launch_speed(p.grid, j) * std::sqrt(1.0 - j.b_fraction * j.b_fraction), 0.1);
  // The table is symmetric in the diameters; the diagonal counts each impact once.
  std::vector<PairOutcome> out;
  for (std::size_t k = 0; k < jobs.size(); ++k) out.push_back(k % 3 == 0 ? PairOutcome::stick : PairOutcome::bounce);
  const OutcomeGridResult t = tabulate_outcomes(p.grid, out);
  for (std::size_t iv = 0; iv < 2; ++iv)
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t b = 0; b < 3; ++b) {
        EXPECT_EQ(t.impacts[t.index(iv, a, b)], 400);
        EXPECT_EQ(t.sticks[t.index(iv, a, b)], t.sticks[t.index(iv, b, a)]);
        EXPECT_EQ(t.sticks[t.index(iv, a, b)] + t.bounces[t.index(iv, a, b)], 400);
      }
}

// The estimate bounds the particle-steps the impacts take and grows with the impacts per node.
TEST(OutcomeGrid, EstimateBoundsTheSteps) {
  const Parsed p = parse_pair("speeds = [0.01, 0.04]\ndiameters = [20e-6]\nimpacts = 2\nmax_offset = 0.5\n");
  long steps = 0;
  for (const auto& j : outcome_impacts(p.grid))
    steps += run_impact(outcome_case(p.dem, p.grid, j), outcome_launch_speed(p.grid, j)).steps;
  const Estimate e = outcomes_estimate(p.dem, p.grid, 1);
  EXPECT_GE(e.steps.value, 2.0 * static_cast<double>(steps));  // two particles per step
  Parsed twice = p;
  twice.grid.impacts = 4;
  EXPECT_DOUBLE_EQ(outcomes_estimate(twice.dem, twice.grid, 1).steps.value, 2.0 * e.steps.value);
  EXPECT_EQ(e.steps.keys.front(), "outcome_grid.speeds");
}

TEST(OutcomeGrid, WilsonInterval) {
  // Wilson (1927) score interval at z = 1.96: 0 of 10 -> [0, 0.2775]; 5 of 10 -> [0.2366, 0.7634].
  EXPECT_NEAR(wilson_interval(0, 10).lo, 0.0, 1e-12);
  EXPECT_NEAR(wilson_interval(0, 10).hi, 0.27753, 1e-5);
  EXPECT_NEAR(wilson_interval(5, 10).lo, 0.23659, 1e-5);
  EXPECT_NEAR(wilson_interval(5, 10).hi, 0.76341, 1e-5);
  EXPECT_NEAR(wilson_interval(10, 10).hi, 1.0, 1e-12);
}

TEST(OutcomeGrid, RefusesOtherCases) {
  const auto refused = [](const std::string& toml, const std::string& needle) {
    try {
      Config cfg = Config::from_string(toml, "bad.toml");
      const ImpactCase c = parse_impact_case(cfg, true);
      check_sphere_sphere(cfg.root(), c);
      (void)parse_outcome_grid(cfg.root());
      ADD_FAILURE() << "accepted: " << needle;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  refused(pair_case("speeds = [0.2, 0.1]\ndiameters = [1e-6]\n"), "key 'outcome_grid.speeds'");
  refused(pair_case("speeds = [0.1]\n"), "outcome_grid.diameters");
  refused(pair_case("speeds = [0.1]\ndiameters = [1e-6, 1e-6]\n"), "strictly increasing");
  std::string two = pair_case("speeds = [0.1]\ndiameters = [1e-6]\n");
  two.replace(two.find("[time]"), 6, "[[particles]]\nposition = [30e-6, 0.0, 0.0]\nradius = 10e-6\n[time]");
  refused(two, "needs a one-sphere target");
  std::string fixed_dt = pair_case("speeds = [0.1]\ndiameters = [1e-6]\n");
  fixed_dt.replace(fixed_dt.find("[time]"), 6, "[time]\ndt = 1e-10");
  refused(fixed_dt, "key 'time.dt' = 1e-10: agglo outcomes takes each node's step");
  // Without the option a one-sphere list target is still refused (collide, vcrit, breakup).
  Config cfg = Config::from_string(pair_case("speeds = [0.1]\ndiameters = [1e-6]\n"), "pair.toml");
  EXPECT_THROW((void)parse_impact_case(cfg), ConfigError);
}
