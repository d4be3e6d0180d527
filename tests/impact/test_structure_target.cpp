// The structure builder as impact target (impact/structure_target.hpp): the generated primaries placed
// with every contact at the JKR equilibrium overlap, charges alternating, the case keys checked.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "agglo/core/config.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/dem/jkr.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/structure/validate.hpp"

namespace agglo::impact {
namespace {

ImpactCase fractal_case(const std::string& extra = "") {
  Config cfg = Config::from_string("[agglomerate]\nseed = 4\nshape = \"fractal\"\nprimaries = 64\nradius = 1e-5\n" + extra);
  return parse_impact_case(cfg);
}

TEST(StructureTarget, ContactsStartAtTheJkrEquilibriumOverlap) {
  const ImpactCase c = fractal_case();
  const dem::Particles p = build_agglomerate(c);
  ASSERT_EQ(p.size(), 64u);
  const auto contacts = structure::validate_structure(c.agglomerate.structure, "shape");
  const double r = 1e-5;
  const double delta0 = dem::JkrPair::make(0.5 * r, c.dem.contact.estar(), c.dem.contact.surface_energy).delta_equilibrium();
  ASSERT_GT(delta0, 0.0);
  for (const auto& [i, j] : contacts.pairs)  // generated touching pairs now overlap by delta0
    EXPECT_NEAR(2.0 * r - norm(p.x[i] - p.x[j]), delta0, 1e-9 * delta0);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)  // no pair deeper than a contact
      EXPECT_LE(2.0 * r - norm(p.x[i] - p.x[j]), delta0 * (1.0 + 1e-9));
}

TEST(StructureTarget, ChargedPrimariesAlternate) {
  const ImpactCase c = fractal_case("charged = true\ncharge_density = 1e-5\n");
  const dem::Particles p = build_agglomerate(c);
  const double q = 1e-5 * 4.0 * constants::pi * 1e-10;
  EXPECT_DOUBLE_EQ(p.q[0], q);
  EXPECT_DOUBLE_EQ(p.q[1], -q);
  EXPECT_TRUE(c.electrostatics);
}

TEST(StructureTarget, KeysOfOtherShapesAndOrientationAreRejected) {
  Config square = Config::from_string("[agglomerate]\nshape = \"square\"\nprimaries = 10\n");
  EXPECT_THROW(parse_impact_case(square), ConfigError);
  Config oriented = Config::from_string("[agglomerate]\nshape = \"bcca\"\norientation = \"face\"\n");
  EXPECT_THROW(parse_impact_case(oriented), ConfigError);
  Config no_file = Config::from_string("[agglomerate]\nshape = \"file\"\n");
  EXPECT_THROW(parse_impact_case(no_file), ConfigError);
}

TEST(StructureTarget, OtherShapesKeepTheirResolvedConfig) {
  Config plain = Config::from_string("[agglomerate]\nshape = \"tetrahedron\"\n");
  (void)parse_impact_case(plain);
  const std::string resolved = plain.resolved_toml();
  EXPECT_EQ(resolved.find("primaries"), std::string::npos);
  EXPECT_EQ(resolved.find("seed"), std::string::npos);
}

}  // namespace
}  // namespace agglo::impact
