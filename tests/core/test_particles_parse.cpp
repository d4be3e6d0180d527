// [[particles]] is parsed once (es::parse_particle) for the electrostatics command and for impact
// cases with agglomerate.shape = "list"; model checks on the spheres are mapped to the section.
#include <gtest/gtest.h>

#include <string>

#include "agglo/core/error.hpp"
#include "agglo/electrostatics/config.hpp"
#include "agglo/impact/impact_case.hpp"

using namespace agglo;

namespace {

const char* kTwoSpheres =
    "[electrostatics]\nmin_gap = 0.02\n"
    "[[particles]]\nposition = [0.0, 0.0, 0.0]\nradius = 1e-5\ncharge = 1e-14\npermittivity = 10.0\n"
    "[[particles]]\nposition = [0.0, 0.0, 2.1e-5]\nradius = 1e-5\n";

std::string es_error(const std::string& toml) {
  try {
    auto cfg = Config::from_string(toml, "case.toml");
    es::parse_electrostatics_case(cfg);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ParticlesParse, ElectrostaticsCase) {
  auto cfg = Config::from_string(kTwoSpheres, "case.toml");
  const auto c = es::parse_electrostatics_case(cfg);
  ASSERT_EQ(c.problem.spheres.size(), 2u);
  EXPECT_DOUBLE_EQ(c.problem.spheres[0].radius, es::electrostatic_radius(1e-5, 0.02));
  EXPECT_DOUBLE_EQ(c.problem.spheres[0].charge, 1e-14);
  EXPECT_DOUBLE_EQ(c.problem.spheres[0].permittivity, 10.0);
  EXPECT_DOUBLE_EQ(c.problem.spheres[1].charge, 0.0);
  EXPECT_DOUBLE_EQ(c.problem.spheres[1].permittivity, 1.0);
  EXPECT_DOUBLE_EQ(c.problem.spheres[1].center.z, 2.1e-5);
  EXPECT_NE(cfg.resolved_toml().find("permittivity = 1.0"), std::string::npos);
}

TEST(ParticlesParse, ElectrostaticsErrors) {
  EXPECT_EQ(es_error("[electrostatics]\n"), "case.toml: key 'particles': at least one [[particles]] entry is required");
  const std::string overlap = es_error(std::string(kTwoSpheres) + "[[particles]]\nposition = [0.0, 1.0e-5, 0.0]\nradius = 1e-5\n");
  EXPECT_EQ(overlap.rfind("case.toml: key 'particles': ", 0), 0u) << overlap;
  EXPECT_NE(overlap.find("overlap"), std::string::npos) << overlap;
  EXPECT_NE(es_error(std::string(kTwoSpheres) + "permittivity = -1.0\n").find("particles.1.permittivity' = -1"),
            std::string::npos);
  EXPECT_NE(es_error(std::string(kTwoSpheres) + "colour = 1\n").find("unknown key 'particles.1.colour'"),
            std::string::npos);
}

TEST(ParticlesParse, ImpactListShapeUsesTheSameEntries) {
  auto cfg = Config::from_string(std::string(kTwoSpheres) + "[agglomerate]\nshape = \"list\"\n", "case.toml");
  const auto c = impact::parse_impact_case(cfg);
  ASSERT_EQ(c.agglomerate.particles.size(), 2u);
  EXPECT_DOUBLE_EQ(c.agglomerate.particles[0].radius, 1e-5);  // the DEM keeps the true radius
  EXPECT_DOUBLE_EQ(c.agglomerate.particles[1].permittivity, 1.0);
  auto wrong = Config::from_string(kTwoSpheres, "case.toml");
  try {
    impact::parse_impact_case(wrong);
    FAIL() << "particles without shape = list accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("agglomerate.shape"), std::string::npos) << e.what();
  }
}
