// The charge and permittivity axes of agglo outcomes (impact/outcome_grid.hpp, docs/outcomes.md "Charge and
// permittivity"): the partners' charges sigma pi d^2 and permittivity per node, the job list, and a tiny
// charged sphere-sphere table run by the DEM whose opposite-charged node sticks where the like-charged and
// the uncharged ones bounce.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/core/config.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/impact/outcome_grid.hpp"
#include "agglo/io/dataset.hpp"
#include "agglo/writers/outcomes.hpp"
#include "outcome_case_helpers.hpp"
#include "sphere_grid_helpers.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

// Two 1 um spheres of the seed material (cases/outcomes_sphere_sphere.toml: E = 1 GPa, gamma = 0.01 J/m^2,
// alpha(0.7) damping, friction 0.3), head-on; electrostatics.min_gap = 0.05 keeps the JKR overlap of the
// fastest impacts within the electrostatic regularisation.
std::string charged_pair_case(const std::string& grid) {
  return test::seed_material("0.3") + R"([agglomerate]
shape = "list"
[[particles]]
position = [0.0, 0.0, 0.0]
radius = 1e-6
[time]
after_contact = 2e-6
[electrostatics]
min_gap = 0.05
[outcome_grid]
max_offset = 0
impacts = 1
)" + grid;
}

using ChargedGrid = test::SphereGrid;
ChargedGrid parse_charged(const std::string& grid) { return test::parse_sphere_grid(charged_pair_case(grid)); }
OutcomeGridResult run_charged(const ChargedGrid& p) { return test::run_sphere_grid(p); }

}  // namespace

TEST(OutcomeCharges, PartnersGetSigmaPiDSquaredAndThePermittivity) {
  const ChargedGrid p = parse_charged("speeds = [0.5]\ndiameters = [1e-6, 2e-6]\ncharges = [-2e-5, 0.0, 3e-5]\n"
                                      "permittivities = [1.0, 4.0]\n");
  // Size pairs (1,1) and (2,2) take c1 <= c2 (6 each), (1,2) all 9; times 2 permittivities.
  const auto jobs = outcome_impacts(p.grid);
  ASSERT_EQ(jobs.size(), (6u + 6u + 9u) * 2u);
  EXPECT_EQ(outcome_impacts_count(p.grid), jobs.size());
  for (const auto& j : jobs) {
    const ImpactCase c = outcome_case(p.dem, p.grid, j);
    const double d1 = p.grid.diameters[j.i1], d2 = p.grid.diameters[j.i2];
    EXPECT_DOUBLE_EQ(c.agglomerate.particles[0].charge, p.grid.charges[j.c1] * constants::pi * d1 * d1);
    EXPECT_DOUBLE_EQ(c.projectile.charge, p.grid.charges[j.c2] * constants::pi * d2 * d2);
    EXPECT_EQ(c.agglomerate.particles[0].permittivity, p.grid.permittivities[j.ik]);
    EXPECT_EQ(c.projectile.permittivity, p.grid.permittivities[j.ik]);
    EXPECT_EQ(c.electrostatics, p.grid.charges[j.c1] != 0.0 || p.grid.charges[j.c2] != 0.0);
    EXPECT_TRUE(c.miss_is_outcome);
    if (j.i1 == j.i2) {
      EXPECT_LE(j.c1, j.c2);
    }
  }
  // Without the axes nothing changes: the case's charges stay, misses stay errors.
  const ChargedGrid u = parse_charged("speeds = [0.5]\ndiameters = [1e-6]\n");
  const ImpactCase c = outcome_case(u.dem, u.grid, outcome_impacts(u.grid).at(0));
  EXPECT_EQ(c.projectile.charge, 0.0);
  EXPECT_FALSE(c.electrostatics);
  EXPECT_FALSE(c.miss_is_outcome);
  EXPECT_THROW(parse_charged("speeds = [0.5]\ndiameters = [1e-6]\ncharges = [1e-5, -1e-5]\n"), ConfigError);
  EXPECT_THROW(parse_charged("speeds = [0.5]\ndiameters = [1e-6]\npermittivities = [0.0]\n"), ConfigError);
}

// Head-on 1 um pairs at 0.8 m/s with sigma = +-5e-5 C/m^2 (charges 1.6e-16 C; Coulomb energy at contact
// 2.2e-16 J against the 2.1e-16 J of relative motion): uncharged, the pair bounces (its sticking speed is
// 0.4-0.6 m/s); opposite charges hit harder but are held (bound after the contact: they stick); like
// charges bounce. Negative control: the uncharged node of the charged table equals a table without axes.
TEST(OutcomeCharges, OppositeChargesStickWhereLikeChargesBounce) {
  const ChargedGrid p = parse_charged("speeds = [0.8]\ndiameters = [1e-6]\ncharges = [-5e-5, 0.0, 5e-5]\n");
  const OutcomeGridResult t = run_charged(p);
  const auto stick = [&](std::size_t c1, std::size_t c2) { return t.sticks[t.index(0, 0, 0, c1, c2)]; };
  EXPECT_EQ(stick(0, 2), 1);  // - +
  EXPECT_EQ(stick(2, 0), 1);  // + - (the mirrored node)
  EXPECT_EQ(stick(0, 0), 0);  // - -
  EXPECT_EQ(stick(2, 2), 0);  // + +
  EXPECT_EQ(stick(1, 1), 0);  // uncharged
  for (std::size_t i = 0; i < t.impacts.size(); ++i) EXPECT_EQ(t.impacts[i], 1) << i;
  const OutcomeGridResult plain = run_charged(parse_charged("speeds = [0.8]\ndiameters = [1e-6]\n"));
  EXPECT_EQ(plain.sticks[0], stick(1, 1));
  // The table's file carries the charge axes; the DSMC's reader interpolates between them (linear in sigma).
  const acoustics::OutcomeTable r =
      acoustics::outcome_table_from_dataset(writers::outcomes_dataset(t, "charged test"));
  ASSERT_TRUE(r.charged());
  EXPECT_FALSE(r.has_axis(acoustics::kPermittivityAxis));
  acoustics::OutcomeQuery q{0.8, 1e-6, 1e-6, -5e-5, 5e-5};
  EXPECT_DOUBLE_EQ(r.at(q).stick, 1.0);
  q.sigma_i = -2.5e-5;  // halfway between sigma_1 = -5e-5 (sticks) and 0 (bounces), partner +5e-5
  EXPECT_DOUBLE_EQ(r.at(q).stick, 0.5);
  EXPECT_FALSE(r.at(q).clamped);
  q.sigma_j = 6e-5;  // outside the charge axis: clamped and flagged
  EXPECT_TRUE(r.at(q).clamped);
}
