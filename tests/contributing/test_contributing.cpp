// The worked examples of docs/contributing.md, compiled and run: a DEM contact sub-model with its own
// coefficient (constant_rolling.hpp), a kernel mechanism (brownian_free_molecular.hpp), an
// electrostatic solver (isolated_spheres_solver.*) and a command (double_command.hpp). The doc quotes
// these files verbatim (scripts/check_contributing_examples.py, lint.contributing_examples).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "agglo/acoustics/kernels/registry.hpp"
#include "agglo/core/config.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/settings_catalogue.hpp"
#include "agglo/dem/contact/registry.hpp"
#include "agglo/electrostatics/config.hpp"
#include "agglo/electrostatics/estimate.hpp"
#include "agglo/impact/impact_case.hpp"
#include "brownian_free_molecular.hpp"
#include "constant_rolling.hpp"
#include "double_command.hpp"
#include "isolated_spheres_solver.hpp"

using namespace agglo;

namespace {

// ---- A DEM contact sub-model: the header above and this line (or one entry in builtin_models.hpp).
const bool registered = agglo::dem::contact::register_model<agglo::dem::contact::ConstantRolling>();

TEST(Contributing, ConstantRollingMoment) {
  using namespace agglo::dem;
  using namespace agglo::dem::contact;
  ContactParams p;
  p.declared["contact.rolling_friction"] = 0.1;
  const auto jkr = JkrPair::make(5e-6, p.estar(), p.surface_energy);
  const ConstantRolling r(p);
  ContactPoint c;  // at the equilibrium radius a0: F_ne = 0, normal +x
  c.n = {1.0, 0.0, 0.0};
  c.a = jkr.a0;
  c.f_ne = jkr.force_of_a(jkr.a0);
  c.w_rel = {0.0, 0.0, 5.0};
  ContactState s;
  const Vec3 m = r.torque(c, jkr, s);
  EXPECT_NEAR(m.z, -0.1 * jkr.R * 2.0 * jkr.Fc, 1e-9 * jkr.Fc * jkr.R);  // opposes w_rel
  c.w_rel = {5.0, 0.0, 0.0};  // pure twisting: no rolling moment
  EXPECT_EQ(norm(r.torque(c, jkr, s)), 0.0);
}

// Selected from a case file by its name, its coefficient read from its own key, listed by `agglo config`.
TEST(Contributing, ConstantRollingFromACaseFile) {
  ASSERT_TRUE(registered);
  auto cfg = Config::from_string("[contact]\nrolling = \"constant\"\nrolling_friction = 0.25\n", "case.toml");
  const auto c = impact::parse_impact_case(cfg);
  cfg.check_unknown_keys();
  EXPECT_EQ(c.dem.contact.models.rolling, "constant");
  EXPECT_EQ(c.dem.contact.value(dem::contact::ConstantRolling::coefficients[0]), 0.25);
  const dem::ContactLaw law(c.dem.contact);
  EXPECT_EQ(law.names().rolling, "constant");
  const std::string listing = settings::list_text("contact");
  EXPECT_NE(listing.find("contact.rolling_friction"), std::string::npos) << listing;
  EXPECT_NE(listing.find("\"constant\""), std::string::npos) << listing;
  cfg = Config::from_string("[contact]\nrolling_friction = 2\n", "case.toml");
  EXPECT_THROW(impact::parse_impact_case(cfg), ConfigError);  // outside its declared range [0, 1]
}

// ---- A kernel mechanism: beta against the formula, the bounds are majorants, selectable by name.
TEST(Contributing, BrownianFreeMolecularKernel) {
  using namespace agglo::acoustics;
  const Gas gas = Gas::air(298.15, 101325.0, false);
  const Sound snd = Sound::make(gas, false, 140.0, 2000.0);
  const KernelSettings ks;
  const BrownianFreeMolecular k(ks, gas, snd);
  SampleSet p;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  CellBounds cb, half[2];
  cb.need_cbar = half[0].need_cbar = half[1].need_cbar = true;
  for (int i = 0; i < 40; ++i) {
    const double d = 1e-8 * std::pow(1000.0, u(rng)), v = constants::pi * d * d * d / 6;
    const std::size_t s = p.add(u(rng), 0, 0, v, 0, 2000 * v, 1, 0, gas, snd);
    cb.include(p, s, gas);
    half[s % 2].include(p, s, gas);
  }
  const double m0 = p.mass[0], m1 = p.mass[1], kT = constants::k_B * 298.15;
  const double c0 = std::sqrt(8 * kT / (constants::pi * m0)), c1 = std::sqrt(8 * kT / (constants::pi * m1));
  const double s01 = p.d[0] + p.d[1];
  EXPECT_NEAR(k.beta(p, 0, 1, 0.0), constants::pi / 4 * s01 * s01 * std::sqrt(c0 * c0 + c1 * c1),
              1e-12 * k.beta(p, 0, 1, 0.0));
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_LE(k.bound(p, i, cb), k.bound_cell(cb) * (1 + 1e-12));
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (i == j) continue;
      EXPECT_LE(k.beta(p, i, j, 0.0), k.bound(p, i, cb) * (1 + 1e-12));
      EXPECT_LE(k.beta(p, i, j, 0.0), k.bound_pair(half[i % 2], half[j % 2]) * (1 + 1e-12));
    }
  }
  // Appended to a mechanism list, it is selectable by kernels.model and kernels.brownian.
  using Set = MechanismSet<Brownian, BrownianFuchs, BrownianFreeMolecular>;
  EXPECT_EQ(Set::standalone_names().back(), "brownian_free_molecular");
  EXPECT_EQ(Set::brownian_term_names().back(), "brownian_free_molecular");
  const Set set({"brownian_free_molecular"}, ks, gas, snd);
  EXPECT_EQ(set.beta(p, 0, 1, 0.0), k.beta(p, 0, 1, 0.0));
  EXPECT_TRUE(set.needs().thermal_speed);
}

// ---- An electrostatic solver: the files above and this line (or one entry in electrostatics/registry.cpp).
const bool solver_registered =
    agglo::es::register_solver({.name = agglo::es::kIsolatedSolver, .make = &agglo::es::make_isolated_spheres_solver});

// Against its closed form.
TEST(Contributing, IsolatedSpheresSolver) {
  const auto solver = es::make_isolated_spheres_solver({});
  es::Problem p;
  p.spheres = {{{0, 0, 0}, 1e-6, 2e-15, 1.0}, {{3e-6, 0, 0}, 2e-6, -1e-15, 4.0}};
  p.medium_permittivity = 2.0;
  p.external_field = {1e5, 0, 0};
  const es::Solution s = solver->solve(p);
  EXPECT_EQ(solver->name(), "isolated");
  EXPECT_DOUBLE_EQ(s.force[1].x, -1e-15 * 1e5);
  const double self = [&] {
    double u = 0.0;
    for (const auto& b : p.spheres) u += b.charge * b.charge / (8 * constants::pi * constants::eps0 * 2.0 * b.radius);
    return u;
  }();
  EXPECT_NEAR(s.energy, self - 0.5 * (-1e-15) * 1e5 * 3e-6, 1e-12 * self);
  EXPECT_EQ(solver->surface().size(), 2u);
}

// Selected from a case file by its name, listed by `agglo config`, with the default (point-charge)
// cost model in the budgets; a name nobody registered is refused naming the registered ones.
TEST(Contributing, IsolatedSpheresSolverFromACaseFile) {
  ASSERT_TRUE(solver_registered);
  auto cfg = Config::from_string("[electrostatics]\nsolver = \"isolated\"\n\n[[particles]]\nposition = [0.0, 0.0, 0.0]\n"
                                 "radius = 1e-6\ncharge = 1e-15\n", "case.toml");
  const es::EsCase c = es::parse_electrostatics_case(cfg);
  EXPECT_EQ(c.settings.options.solver, "isolated");
  EXPECT_EQ(es::make_solver(c.settings.options)->name(), "isolated");
  EXPECT_NE(settings::list_text("electrostatics").find("isolated"), std::string::npos);
  const Estimate e = es::static_solve_estimate(c.settings.options, c.problem);
  EXPECT_EQ(e.steps.value, 1.0);  // N^2 interactions, N = 1
  EXPECT_TRUE(es::induces_charges(c.settings.options));
  auto bad = Config::from_string("[electrostatics]\nsolver = \"isolate\"\n", "case.toml");
  try {
    es::parse_electrostatics(es::solver_keys().t.open(bad.root()));
    FAIL() << "an unknown solver was accepted";
  } catch (const ConfigError& err) {
    EXPECT_NE(std::string(err.what()).find("isolated"), std::string::npos) << err.what();
  }
}

// ---- A command: run through run::execute like every command (folder, config.resolved.toml, run.json).
TEST(Contributing, DoubleCommand) {
  const run::DoubleCommand cmd;
  auto cfg = Config::from_string("[double]\nvalue = 21\n", "case.toml");
  const auto dir = std::filesystem::temp_directory_path() / ("agglo_contributing_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const run::CommandResult r = run::execute(cmd, cfg, dir, run::RunContext{});
  EXPECT_EQ(r.summary["twice"], 42.0);
  EXPECT_TRUE(std::filesystem::exists(dir / "config.resolved.toml"));
  EXPECT_TRUE(std::filesystem::exists(dir / "run.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "result.json"));
  std::filesystem::remove_all(dir);
  cfg = Config::from_string("[double]\nvalue = \"x\"\n", "case.toml");
  EXPECT_THROW(run::execute(cmd, cfg, dir, run::RunContext{}), ConfigError);
}

}  // namespace
