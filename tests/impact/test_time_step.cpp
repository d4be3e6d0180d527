// The time step of the impact runs (impact/estimate.hpp time_step, used by the estimate and by every
// run): the shortest contact period among the launch particles' pairs and wall contacts. A rigid wall
// is stiffer than the pair of two equal spheres (R* = r, m* = m, E* twice the like pair's), and a
// projectile smaller than the agglomerate's primaries has a shorter period than they have; before,
// the runs took the step of the agglomerate alone (a 1 um projectile on the 10 um tetrahedron ran at
// T0/3 of its own period) and the estimate ignored the walls.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "agglo/core/config.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/dem/jkr.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/estimate.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/impact_case.hpp"

namespace agglo::impact {
namespace {

ImpactCase shipped(const std::string& name, const std::vector<std::string>& sets) {
  Config cfg = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/" + name);
  for (const auto& s : sets) cfg.apply_override(s);
  return parse_impact_case(cfg);
}

// T0 = 2 pi sqrt(m* / k0), k0 = 0.9905 F_C / delta_C (dem::reference_period's definition).
double period(double R, double mstar, double estar, double gamma) {
  const auto jkr = dem::JkrPair::make(R, estar, gamma);
  return 2.0 * constants::pi * std::sqrt(mstar / (0.9905 * jkr.Fc / jkr.deltaC));
}

TEST(TimeStep, RigidWallIsShorterThanThePair) {
  const ImpactCase c = shipped("sphere_wall.toml", {"wall.material=\"rigid\"", "time.after_contact=2e-6"});
  const auto& cp = c.dem.contact;
  const double r = 10e-6, m = 2500.0 * 4.0 / 3.0 * constants::pi * r * r * r;
  const double nu2 = 1.0 - cp.poisson_ratio * cp.poisson_ratio;
  const double wall = period(r, m, cp.youngs_modulus / nu2, cp.surface_energy);            // rigid: E* = E/(1-nu^2)
  const double pair = period(0.5 * r, 0.5 * m, cp.estar(), cp.surface_energy);             // like pair
  ASSERT_LT(wall, pair);
  EXPECT_NEAR(time_step(c), wall / c.dem.steps_per_period, 1e-9 * time_step(c));
  EXPECT_EQ(run_impact(c, 0.04).dt, time_step(c));
}

TEST(TimeStep, SmallProjectileSetsTheStep) {
  const std::vector<std::string> short_run{"time.after_contact=2e-6", "projectile.speed=1.0"};
  const ImpactCase same = shipped("seed000_neutral_tetrahedron.toml", short_run);
  auto sets = short_run;
  sets.push_back("projectile.radius=1e-6");
  const ImpactCase small = shipped("seed000_neutral_tetrahedron.toml", sets);
  const auto& cp = small.dem.contact;
  const double rp = 1e-6, mp = 2500.0 * 4.0 / 3.0 * constants::pi * rp * rp * rp;
  const double own = period(0.5 * rp, 0.5 * mp, cp.estar(), cp.surface_energy);  // the projectile's own scale
  EXPECT_LE(time_step(small), own / small.dem.steps_per_period * (1.0 + 1e-12));
  EXPECT_LT(5.0 * time_step(small), time_step(same));
  EXPECT_EQ(run_impact(small, 1.0).dt, time_step(small));
  EXPECT_EQ(run_impact(same, 1.0).dt, time_step(same));
}

}  // namespace
}  // namespace agglo::impact
