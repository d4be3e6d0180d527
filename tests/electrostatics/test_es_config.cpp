// [electrostatics] parsing, defaults, range checks, and the min-gap radius helper (docs/model.md §B.3).
#include <gtest/gtest.h>

#include "agglo/core/config.hpp"
#include "agglo/core/error.hpp"
#include "agglo/electrostatics/config.hpp"

using namespace agglo;
using namespace agglo::es;

TEST(EsConfig, DefaultsAreWrittenBack) {
  auto cfg = Config::from_string("[electrostatics]\n");
  auto ec = parse_electrostatics(cfg.root().section("electrostatics"));
  cfg.check_unknown_keys();
  EXPECT_EQ(ec.options.solver, "spectral");
  EXPECT_EQ(ec.medium_permittivity, 1.0);
  EXPECT_EQ(ec.min_gap, 0.01);
  EXPECT_EQ(ec.update_fraction, 0.01);
  EXPECT_EQ(ec.update_interval, 0);
  EXPECT_FALSE(ec.force_scale_chi);
  EXPECT_EQ(ec.options.target_accuracy, 1e-4);
  EXPECT_EQ(ec.options.patches_per_sphere, 2000);
  EXPECT_EQ(ec.options.matvec, "fmm");
  EXPECT_EQ(ec.options.far_field, "dense");
  EXPECT_EQ(ec.options.preconditioner, "none");
  auto txt = cfg.resolved_toml();
  for (auto key : {"min_gap", "update_fraction", "target_accuracy", "patches_per_sphere", "external_field", "matvec"})
    EXPECT_NE(txt.find(key), std::string::npos) << key;
  // electrostatics.preconditioner is read only when set: a case that does not name it resolves as before
  EXPECT_EQ(txt.find("preconditioner"), std::string::npos) << txt;
  EXPECT_EQ(ec.options.contact_low_steps, kContactLowSteps);  // and so is preconditioner_steps
}

TEST(EsConfig, ValuesAndRangeErrors) {
  auto cfg = Config::from_string(
      "[electrostatics]\nsolver='coulomb'\nmedium_permittivity=2.5\nmin_gap=0\nexternal_field=[1,2,3]\n"
      "max_degree=30\nmatvec='direct'\nupdate_interval=10\nforce_scale_chi=true\nfar_field='fmm'\n"
      "preconditioner='contact_low'\npreconditioner_steps=3\n");
  auto ec = parse_electrostatics(cfg.root().section("electrostatics"));
  EXPECT_EQ(ec.options.solver, "coulomb");
  EXPECT_EQ(ec.medium_permittivity, 2.5);
  EXPECT_EQ(ec.min_gap, 0.0);
  EXPECT_EQ(ec.external_field.z, 3.0);
  EXPECT_EQ(ec.options.max_degree, 30);
  EXPECT_EQ(ec.options.matvec, "direct");
  EXPECT_EQ(ec.update_interval, 10);
  EXPECT_TRUE(ec.force_scale_chi);
  EXPECT_EQ(ec.options.far_field, "fmm");
  EXPECT_EQ(ec.options.preconditioner, "contact_low");
  EXPECT_EQ(ec.options.contact_low_steps, 3);
  for (const char* bad : {"medium_permittivity=0", "medium_permittivity=-1", "medium_permittivity=1e300", "min_gap=-0.1",
                          "update_fraction=0", "update_fraction=1.5", "solver='fast'", "matvec='gpu'", "far_field='tree'", "preconditioner='ilu'", "preconditioner_steps=0",
                          "preconditioner_steps=17", "tolerance=0",
                          "max_degree=-1", "max_degree=100", "target_accuracy=2"}) {
    auto c = Config::from_string(std::string("[electrostatics]\n") + bad + "\n", "case.toml");
    try {
      parse_electrostatics(c.root().section("electrostatics"));
      ADD_FAILURE() << "accepted " << bad;
    } catch (const ConfigError& e) {
      std::string msg = e.what();
      EXPECT_NE(msg.find("case.toml"), std::string::npos) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      std::string key = std::string(bad).substr(0, std::string(bad).find('='));
      EXPECT_NE(msg.find(key), std::string::npos) << msg;
    }
  }
}

TEST(EsConfig, ShrinkingAndOverlapChecks) {
  EsConfig ec;  // g_min = 0.01
  const double r = 10e-6;
  EXPECT_DOUBLE_EQ(electrostatic_radius(r, 0.01), r / 1.005);
  // touching spheres (and slightly overlapping ones, e.g. at the JKR equilibrium overlap) are
  // separated by the regularisation: gap = 2r - 2r/1.005 - overlap
  auto p = make_problem(ec, {Vec3{0, 0, 0}, Vec3{2 * r - 3.6e-9, 0, 0}}, {r, r}, {1e-14, -1e-14}, {15, 15});
  EXPECT_NEAR(smallest_gap(p), 2 * r - 3.6e-9 - 2 * r / 1.005, 1e-15);
  EXPECT_EQ(p.spheres[0].charge, 1e-14);
  // overlapping beyond the regularisation
  EXPECT_THROW(make_problem(ec, {Vec3{0, 0, 0}, Vec3{1.98 * r, 0, 0}}, {r, r}, {0, 0}, {2, 2}), NumericalError);
  EXPECT_THROW(make_problem(ec, {Vec3{0, 0, 0}, Vec3{3 * r, 0, 0}}, {r, 0.0}, {0, 0}, {2, 2}), NumericalError);
  EXPECT_THROW(make_problem(ec, {Vec3{0, 0, 0}, Vec3{3 * r, 0, 0}}, {r, r}, {0, 0}, {2, 0.0}), NumericalError);
  EXPECT_THROW(make_problem(ec, {Vec3{0, 0, 0}, Vec3{3 * r, 0, 0}}, {r, r}, {0, 0}, {2, -1.0}), NumericalError);
  Problem q = p;
  q.spheres[1].center.x = r;
  EXPECT_THROW(check_particles(q, "case.toml"), ConfigError);
}
