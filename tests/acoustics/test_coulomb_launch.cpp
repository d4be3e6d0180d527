// The Coulomb work before a charged table's launch gap (acoustics/coulomb_launch.hpp, docs/acoustics.md §1.7):
// the speed conversion against a hand calculation, its negative controls, and a run of like-charged samples at
// rest whose every dry collision is turned back before the launch separation (a bounce), while the same table
// without the launch gap (negative control) lets them stick.
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "agglo/acoustics/coulomb_launch.hpp"
#include "agglo/acoustics/outcome_table.hpp"
#include "helpers.hpp"
#include "outcome_table_helpers.hpp"

using namespace agglo::acoustics;

// Two 1 um spheres of 2500 kg/m^3 (m = 1.3089969e-15 kg, mu = m/2), sigma = 5e-5 C/m^2 (q = 1.5707963e-16 C),
// launch gap g = 1 (s = 1.5 um), kappa_0 = 1: U(s) = q^2 / (4 pi eps_0 s) = 1.4783930e-16 J,
// 2U/mu = 0.45176363 m^2/s^2 (computed by hand, python, eps_0 = 8.8541878128e-12 F/m).
TEST(CoulombLaunch, SpeedAtTheLaunchGapByHand) {
  const double d = 1e-6, m = 2500.0 * 3.14159265358979 / 6.0 * d * d * d, q = 1.5707963267948964e-16;
  EXPECT_NEAR(coulomb_launch_speed(1.0, q, q, m, m, d, d, 1.0, 1.0), 0.7404298569417581, 1e-9);   // like: slower
  EXPECT_NEAR(coulomb_launch_speed(1.0, q, -q, m, m, d, d, 1.0, 1.0), 1.2048915415709447, 1e-9);  // opposite: faster
  EXPECT_EQ(coulomb_launch_speed(0.5, q, q, m, m, d, d, 1.0, 1.0), -1.0);  // 0.25 < 0.4518: turned back
  EXPECT_NEAR(coulomb_launch_speed(0.7, q, q, m, m, d, d, 1.0, 1.0), std::sqrt(0.49 - 0.45176362694920763), 1e-9);
  // kappa_0 = 2 halves U; a gap of 3 radii (s = 2.5 um) takes 3/5 of it
  EXPECT_NEAR(coulomb_launch_speed(1.0, q, q, m, m, d, d, 1.0, 2.0), std::sqrt(1.0 - 0.45176362694920763 / 2), 1e-9);
  EXPECT_NEAR(coulomb_launch_speed(1.0, q, q, m, m, d, d, 3.0, 1.0), std::sqrt(1.0 - 0.45176362694920763 * 0.6), 1e-9);
  // negative control: an uncharged partner leaves the speed as it is
  EXPECT_EQ(coulomb_launch_speed(1.0, q, 0.0, m, m, d, d, 1.0, 1.0), 1.0);
}

namespace {

// A charged table over (speed, d, d, sigma, sigma) with P_stick = 1 at every node; with the launch gap g = 1,
// kappa_0 = 1 when `gap`.
OutcomeTable sticky_charged_table(bool gap) {
  OutcomeTable t;
  t.axes[kSpeedAxis] = {1e-4, 100.0};
  t.axes[kDiameter1Axis] = {1e-9, 1e-3};
  t.axes[kDiameter2Axis] = {1e-9, 1e-3};
  t.axes[kCharge1Axis] = {-1e-3, 1e-3};
  t.axes[kCharge2Axis] = {-1e-3, 1e-3};
  t.p_stick.assign(t.nodes(), 1.0);
  t.p_bounce.assign(t.nodes(), 0.0);
  t.p_break.assign(t.nodes(), 0.0);
  if (gap) t.launch_gap = 1.0, t.medium_permittivity = 1.0;
  return t;
}

}  // namespace

// Like charges (sigma = 2e-5 C/m^2) at rest (v_n = 0): every dry collision is turned back and bounces, none
// sticks although P_stick = 1; without the launch gap the same pairs stick (negative control).
TEST(CoulombLaunch, LikeChargesAtRestAreTurnedBack) {
  for (const bool gap : {true, false}) {
    const std::string file =
        test::write_table_dataset(outcome_table_dataset(sticky_charged_table(gap)), gap ? "launch" : "nolaunch").string();
    std::string toml = test::constant_kernel_case(3, fmt::format("dry_model = \"table\"\ntable = \"{}\"", file), 0.1);
    toml.replace(toml.find("samples = 4000\n"), 15, "samples = 1000\ncharge_density = 2e-5\n");
    Engine e = test::make_engine(toml);
    while (e.time() < e.settings().t_end - 1e-9) e.step();
    const auto& s = e.stats();
    if (gap) {
      EXPECT_GT(s.table_turned_back, 20u);
      EXPECT_EQ(s.coalescences[1], 0u);
      EXPECT_EQ(s.rebounds[1], s.table_turned_back);
      EXPECT_EQ(s.table_queries, 0u);  // turned back before the lookup
    } else {
      EXPECT_EQ(s.table_turned_back, 0u);
      EXPECT_GT(s.coalescences[1], 20u);
      EXPECT_EQ(s.rebounds[1], 0u);
    }
  }
}
