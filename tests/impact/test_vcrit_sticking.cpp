// vcrit.criterion = "sticking" (impact/vcrit.hpp, docs/dem.md): the undamped sphere-wall sticking
// velocity found by the vcrit bisection of full impact runs against the closed form
// v_s = 1.3679 sqrt(F_C delta_C / m) with the wall's R* = r, m* = m (docs/model.md §A.5), for a wall of
// the sphere's material and a rigid one; a projectile staying on the target; the criterion parsed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/dem/wall.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/impact/vcrit.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

// One sphere (seed material, r = 10 um) moving onto a wall 0.5 um ahead, no damping or friction, the
// contact resolved by 800 steps per period.
ImpactCase sphere_wall(const std::string& wall_material) {
  Config cfg = Config::from_string(R"(
[material]
density = 2500.0
youngs_modulus = 1e9
poisson_ratio = 0.33
surface_energy = 0.01
friction = 0.0
[contact]
damping = "none"
[agglomerate]
shape = "list"
[[particles]]
position = [0.0, 0.0, 0.0]
radius = 10e-6
[wall]
position = [10.5e-6, 0.0, 0.0]
normal = [-1.0, 0.0, 0.0]
material = ")" + wall_material + R"("
impact = true
[time]
steps_per_period = 800
after_contact = 1e-4
[vcrit]
criterion = "sticking"
v_min = 0.01
v_max = 0.04
scan_points = 4
tolerance = 2e-6
)");
  return parse_impact_case(cfg);
}

double closed_form(dem::WallMaterial w) {
  const double r = 10e-6, m = 4.0 / 3.0 * constants::pi * r * r * r * 2500.0;
  const auto jkr = dem::JkrPair::make(r, dem::wall_estar(w, 1e9, 0.33), 0.01);
  return 1.3679 * std::sqrt(jkr.Fc * jkr.deltaC / m);
}

VcritResult bisect_sticking(const ImpactCase& c) {
  auto batch = [&](const std::vector<double>& speeds, const StopRule&) {
    std::vector<ImpactOutcome> out;
    for (double v : speeds) out.push_back(run_impact(c, v));
    return out;
  };
  return find_vcrit(c.vcrit, batch);
}

}  // namespace

TEST(VcritSticking, CriterionParsed) {
  EXPECT_TRUE(sphere_wall("same").vcrit.sticking);
  Config plain = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/sphere_wall.toml");
  EXPECT_FALSE(parse_impact_case(plain).vcrit.sticking);
}

TEST(VcritSticking, SphereOnSameMaterialWall) {
  const VcritResult res = bisect_sticking(sphere_wall("same"));
  const double vs = closed_form(dem::WallMaterial::same);  // 0.02514 m/s
  EXPECT_TRUE(res.sticking);
  EXPECT_EQ(res.v_crit, res.lo);
  EXPECT_LE(res.hi - res.lo, 2e-6);
  EXPECT_NEAR(res.v_crit / vs, 1.0, 2e-3) << "v_crit " << res.v_crit << " closed form " << vs;
  // Outside a band of 0.5 % around v_s the outcome is monotonic: below it stays, above it rebounds.
  // (Within 0.1 % of v_s the discrete runs are not: at dt = T0/800, 0.025158 and 0.025176 m/s
  // rebounded while 0.025181 m/s stayed; vcrit reports that as a non-monotonic warning.)
  for (const auto& o : res.runs) {
    if (std::abs(o.speed / vs - 1.0) > 5e-3) {
      EXPECT_EQ(stays(o), o.speed < vs) << o.speed;
    }
  }
  for (const auto& w : res.warnings) EXPECT_NE(w.find("non-monotonic"), std::string::npos) << w;
}

TEST(VcritSticking, SphereOnRigidWall) {
  const VcritResult res = bisect_sticking(sphere_wall("rigid"));
  const double vs = closed_form(dem::WallMaterial::rigid);  // 0.01996 m/s
  EXPECT_NEAR(res.v_crit / vs, 1.0, 2e-3) << "v_crit " << res.v_crit << " closed form " << vs;
}

TEST(VcritSticking, ProjectileStaysOnTarget) {
  // The seed tetrahedron hit at 0.01 m/s: the projectile stays on it; stays() looks at the projectile's
  // component at the end (alone: not stuck).
  Config cfg = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/seed000_neutral_tetrahedron.toml");
  ImpactCase c = parse_impact_case(cfg);
  c.time.after_contact = 2e-4;
  const ImpactOutcome slow = run_impact(c, 0.01);
  ASSERT_TRUE(slow.contact);
  EXPECT_TRUE(stays(slow));
  ImpactOutcome none;
  EXPECT_FALSE(stays(none));  // no contact: not stuck
  ImpactOutcome alone = slow;
  alone.components = {{0, 1, 2, 3}, {4}};  // the projectile (highest index) on its own
  alone.breakage.wall = WallOutcome::none;
  EXPECT_FALSE(stays(alone));
  alone.components = {{0, 1, 2, 3}, {4, 5}};  // a projectile of two primaries, together but off the target
  EXPECT_FALSE(stays(alone));
  alone.components = {{0, 1, 2, 3, 5}, {4}};  // one of them on the target
  EXPECT_TRUE(stays(alone));
}
