// Aggregate outcome tables over the partners' primary radii (outcome_grid.primary_radii, impact/outcome_grid.hpp,
// docs/outcomes.md "Primary radii"): the common volume-equivalent size axis 2 a_0 N^(1/3), each partner built
// with its own primary radius and count, the symmetric copies, the written primary_radius_1/2 axes read back
// by the DSMC's reader at the right node, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/core/config.hpp"
#include "agglo/core/error.hpp"
#include "agglo/impact/outcome_aggregates.hpp"
#include "agglo/writers/outcomes.hpp"
#include "outcome_case_helpers.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

constexpr double kA0 = 0.5e-6;  // the first primary radius [m]

// Two BPCA partners of the seed material; primary radii a_0 and 2^(1/3) a_0 by the grid (counts halve at the second).
using RadiiParsed = test::AggregateGrid;
RadiiParsed parse_radii(const std::string& grid) { return test::parse_aggregate_grid(grid); }

const std::string kTwoRadii = "speeds = [0.1, 30.0]\nprimaries = [4]\nimpacts = 1\nmax_offset = 0\n"
                              "primary_radii = [0.5e-6, 6.299605249474366e-7]\n";  // a_0, 2^(1/3) a_0

double sum_of(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s;
}

}  // namespace

// Node (N, a): the target of node (a_1, a_2) has N (a_0/a_1)^3 primaries of a_1, the projectile its own; both
// keep the volume-equivalent diameter of the common axis; the nodes run are (a_0, a_0), (a_0, a_1), (a_1, a_1).
TEST(OutcomePrimaryRadii, EachPartnerBuiltWithItsOwnRadius) {
  const RadiiParsed p = parse_radii(kTwoRadii);
  ASSERT_EQ(p.grid.diameters.size(), 1u);
  EXPECT_DOUBLE_EQ(p.grid.diameters[0], 2.0 * kA0 * std::cbrt(4.0));
  EXPECT_EQ(p.grid.partner_primaries(0, 0), 4);
  EXPECT_EQ(p.grid.partner_primaries(0, 1), 2);
  const auto jobs = outcome_impacts(p.grid);
  ASSERT_EQ(jobs.size(), 2u * 3u);  // 2 speeds x the 3 radius pairs m1 <= m2 of the one size
  EXPECT_EQ(outcome_impacts_count(p.grid), jobs.size());
  const OutcomeImpact& mixed = jobs[1];
  ASSERT_EQ(mixed.m1, 0u);
  ASSERT_EQ(mixed.m2, 1u);
  const ImpactCase c = outcome_case(p.dem, p.grid, mixed);
  EXPECT_EQ(c.agglomerate.structure.size(), 4u);
  EXPECT_EQ(c.projectile.body.structure.size(), 2u);
  const auto m = pair_masses(c);
  ASSERT_EQ(m.size(), 6u);
  // the projectile's primaries are twice as heavy; each partner holds half the pair's mass (same d)
  EXPECT_NEAR(m[4] / m[0], 2.0, 1e-12);
  EXPECT_NEAR(sum_of({m.begin(), m.begin() + 4}), sum_of({m.begin() + 4, m.end()}), 1e-12 * m[0]);
  // negative control: the node of equal radii has equal primaries
  const auto same = pair_masses(outcome_case(p.dem, p.grid, jobs[0]));
  ASSERT_EQ(same.size(), 8u);
  EXPECT_DOUBLE_EQ(same[7], same[0]);
}

// The DEM grid (0.1 and 30 m/s, 4 primaries at a_0 and 2 at 2^(1/3) a_0, head-on, one impact per node) run,
// tabulated with its mirror copies and read back by the DSMC's reader: the node of partners (a_0, a_1) is its
// own run (its fragments include a single heavy primary of mass fraction 2/8, impossible at (a_0, a_0) where
// every primary is 1/8), its mirror (a_1, a_0) copies it, and the reader queried with the sample's own
// (d, a) finds these nodes.
TEST(OutcomePrimaryRadii, TableReadBackAtTheRightNode) {
  const RadiiParsed p = parse_radii(kTwoRadii);
  const test::AggregateImpacts r = test::run_aggregate_grid(p);
  std::vector<double> nf, fl;
  std::vector<std::vector<double>> fractions;
  for (const auto& f : r.fragments) {
    nf.push_back(f.fragments);
    fl.push_back(f.largest_fraction);
    fractions.push_back(f.fractions);
  }
  const OutcomeGridResult t = tabulate_outcomes(p.grid, r.outcomes(), nf, fl, fractions);
  ASSERT_EQ(t.impacts.size(), 2u * 4u);  // 2 speeds x (a_1, a_2) in {a_0, a_1}^2
  for (auto n : t.impacts) EXPECT_EQ(n, 1);
  const std::size_t fast_mixed = t.index(1, 0, 0, 0, 0, 0, 0, 1), fast_mirror = t.index(1, 0, 0, 0, 0, 0, 1, 0);
  ASSERT_EQ(t.breaks[fast_mixed], 1);  // 30 m/s head-on breaks
  EXPECT_EQ(t.breaks[fast_mirror], 1);
  EXPECT_EQ(t.fragments[fast_mirror], t.fragments[fast_mixed]);
  const std::size_t nb = kFragmentFractionEdges.size() - 1;
  // a single primary of the heavy partner: 2/8 = 0.25, bin 5 [2^-2.5, 2^-1.5)
  const std::size_t heavy_bin = fragment_fraction_bin(0.25), light_bin = fragment_fraction_bin(0.125);
  ASSERT_NE(heavy_bin, light_bin);
  const bool mixed_heavy_single = [&] {
    for (const auto& f : fractions[4]) if (f == 0.25) return true;  // impact 4: (30 m/s, a_0, a_1)
    return false;
  }();
  EXPECT_TRUE(mixed_heavy_single);
  for (const auto& f : fractions[3]) EXPECT_EQ(std::fmod(f * 8.0, 1.0), 0.0);  // (30 m/s, a_0, a_0): k/8
  EXPECT_GT(t.fragment_number[fast_mixed * nb + heavy_bin], 0.0);

  const auto table = acoustics::outcome_table_from_dataset(writers::outcomes_dataset(t, "test"));
  ASSERT_TRUE(table.has_primary_radii());
  EXPECT_EQ(table.axes[acoustics::kPrimaryRadius1Axis], p.grid.primary_radii);
  EXPECT_EQ(table.axes[acoustics::kPrimaryRadius2Axis], p.grid.primary_radii);
  const double d = p.grid.diameters[0];
  acoustics::OutcomeQuery q{30.0, d, d};
  q.rp_i = p.grid.primary_radii[0];
  q.rp_j = p.grid.primary_radii[1];
  const auto pr = table.at(q);
  EXPECT_FALSE(pr.clamped);
  EXPECT_EQ(pr.brk, 1.0);
  const auto fs = table.fragments_at(q);
  EXPECT_DOUBLE_EQ(fs.number, t.fragments[fast_mixed]);
  EXPECT_DOUBLE_EQ(fs.bin_number[heavy_bin], t.fragment_number[fast_mixed * nb + heavy_bin]);
  // the slow nodes: what the runs gave, node by node
  for (std::size_t m1 = 0; m1 < 2; ++m1)
    for (std::size_t m2 = 0; m2 < 2; ++m2) {
      acoustics::OutcomeQuery s{0.1, d, d};
      s.rp_i = p.grid.primary_radii[m1];
      s.rp_j = p.grid.primary_radii[m2];
      const std::size_t i = t.index(0, 0, 0, 0, 0, 0, m1, m2);
      EXPECT_EQ(table.at(s).stick, static_cast<double>(t.sticks[i]));
    }
}

// Refused with one line naming the key: radii that give a count that is not whole or below 2, radii not
// increasing, radii for sphere tables.
TEST(OutcomePrimaryRadii, RefusesCountsThatAreNotWhole) {
  try {
    parse_radii("speeds = [1.0]\nprimaries = [4]\nprimary_radii = [0.5e-6, 0.6e-6]\n");
    FAIL() << "not refused";
  } catch (const ConfigError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("outcome_grid.primary_radii"), std::string::npos) << w;
    EXPECT_NE(w.find("whole"), std::string::npos) << w;
    EXPECT_EQ(w.find('\n'), std::string::npos) << w;
  }
  EXPECT_THROW(parse_radii("speeds = [1.0]\nprimaries = [4]\nprimary_radii = [0.5e-6, 1e-6]\n"), ConfigError);  // 1/2
  EXPECT_THROW(parse_radii("speeds = [1.0]\nprimaries = [4]\nprimary_radii = [0.6e-6, 0.5e-6]\n"), ConfigError);
  EXPECT_NO_THROW(parse_radii("speeds = [1.0]\nprimaries = [16]\nprimary_radii = [0.5e-6, 1e-6]\n"));  // 16, 2
  Config cfg = Config::from_string(R"(
[material]
density = 2500.0
[agglomerate]
shape = "list"
[[particles]]
x = [0.0, 0.0, 0.0]
radius = 1e-6
[outcome_grid]
speeds = [1.0]
diameters = [1e-6]
primary_radii = [0.5e-6]
)",
                                   "spheres.toml");
  EXPECT_THROW(parse_outcome_grid(cfg.root()), ConfigError);
}
