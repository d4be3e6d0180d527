// Aggregate-aggregate outcome tables (impact/outcome_aggregates.hpp, docs/outcomes.md "Aggregate tables"):
// the stick/bounce/break classification on constructed contact graphs, the fragment mass conserved in DEM
// impacts, the diameters 2 a N^(1/3), the per-impact structures, the fragment statistics of the tabulation
// and the table read back by the DSMC's reader.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/core/config.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/impact/outcome_aggregates.hpp"
#include "agglo/writers/outcomes.hpp"
#include "outcome_case_helpers.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

using AggParsed = test::AggregateGrid;
AggParsed parse_aggregates(const std::string& grid, const std::string& extra = "") {
  return test::parse_aggregate_grid(grid, extra);
}

const std::vector<double> kMasses = {1.0, 1.0, 2.0, 2.0};  // target {0, 1}, projectile {2, 3}

}  // namespace

TEST(OutcomeAggregates, ClassifiesConstructedContactGraphs) {
  auto f = classify_aggregate_pair({{0, 1, 2, 3}}, kMasses, 2);
  EXPECT_EQ(f.outcome, PairOutcome::stick);
  EXPECT_EQ(f.fragments, 1);
  EXPECT_EQ(f.largest_fraction, 1.0);
  f = classify_aggregate_pair({{0, 1}, {2, 3}}, kMasses, 2);  // the two partners apart
  EXPECT_EQ(f.outcome, PairOutcome::bounce);
  EXPECT_EQ(f.fragments, 2);
  EXPECT_DOUBLE_EQ(f.largest_fraction, 4.0 / 6.0);
  f = classify_aggregate_pair({{0}, {1, 2, 3}}, kMasses, 2);  // the target cut in two: a primary knocked off
  EXPECT_EQ(f.outcome, PairOutcome::brk);
  EXPECT_EQ(f.fragments, 2);
  EXPECT_DOUBLE_EQ(f.largest_fraction, 5.0 / 6.0);
  EXPECT_DOUBLE_EQ(f.fragment_mass, 6.0);
  EXPECT_EQ(f.fractions, (std::vector<double>{1.0 / 6.0, 5.0 / 6.0}));
  f = classify_aggregate_pair({{0, 2}, {1, 3}}, kMasses, 2);  // two parts, but not the partners
  EXPECT_EQ(f.outcome, PairOutcome::brk);
  f = classify_aggregate_pair({{0, 1}, {2}, {3}}, kMasses, 2);  // the projectile in two, apart from the target
  EXPECT_EQ(f.outcome, PairOutcome::brk);
  EXPECT_EQ(f.fragments, 3);
  EXPECT_DOUBLE_EQ(f.largest_fraction, 1.0 / 3.0);
  EXPECT_THROW(classify_aggregate_pair({{0, 1}, {1, 2, 3}}, kMasses, 2), std::invalid_argument);  // twice
  EXPECT_THROW(classify_aggregate_pair({{0, 1}, {2}}, kMasses, 2), std::invalid_argument);        // 3 missing
}

TEST(OutcomeAggregates, DiametersAndStructuresPerImpact) {
  const AggParsed p = parse_aggregates("speeds = [1.0]\nprimaries = [2, 8]\nimpacts = 2\n");
  ASSERT_EQ(p.grid.diameters.size(), 2u);
  EXPECT_DOUBLE_EQ(p.grid.diameters[0], 2.0 * 0.5e-6 * std::cbrt(2.0));
  EXPECT_DOUBLE_EQ(p.grid.diameters[1], 2.0 * 0.5e-6 * 2.0);
  const auto jobs = outcome_impacts(p.grid);
  ASSERT_EQ(jobs.size(), 3u * 2u);  // (2, 2), (2, 8), (8, 8) x 2 samples
  const ImpactCase a = outcome_case(p.dem, p.grid, jobs[2]), b = outcome_case(p.dem, p.grid, jobs[3]);
  EXPECT_EQ(a.agglomerate.structure.size(), 2u);
  EXPECT_EQ(a.projectile.body.structure.size(), 8u);
  EXPECT_NE(a.agglomerate.seed, b.agglomerate.seed);  // every sample its own structures
  EXPECT_NE(a.projectile.body.seed, b.projectile.body.seed);
  EXPECT_DOUBLE_EQ(a.projectile.offset_radii * 0.5e-6, jobs[2].b_fraction * 0.5 * (p.grid.diameters[0] + p.grid.diameters[1]));
  const auto m = pair_masses(a);
  ASSERT_EQ(m.size(), 10u);
  EXPECT_NEAR(m[0], 2500.0 * 4.0 / 3.0 * constants::pi * std::pow(0.5e-6, 3), 1e-12 * m[0]);
}

TEST(OutcomeAggregates, RefusesWhatItCannotTabulate) {
  EXPECT_THROW(parse_aggregates("speeds = [1.0]\nprimaries = [2, 4]\ndiameters = [1e-6]\n"), ConfigError);
  EXPECT_THROW(parse_aggregates("speeds = [1.0]\nprimaries = [2, 4.5]\n"), ConfigError);
  EXPECT_THROW(parse_aggregates("speeds = [1.0]\nprimaries = [4, 2]\n"), ConfigError);
  EXPECT_THROW(parse_aggregates("speeds = [1.0]\nprimaries = [2, 4]\n", "radius_std = 1.2\n"), ConfigError);
}

// Every DEM impact of a small grid (2 + 2 primaries at 0.1, 3 and 30 m/s) conserves the fragment mass: the
// fragments' masses add up to the pair's; the fast impacts break, with their statistics in the table
// (N_f >= 2, 1/N_f <= f_L < 1, NaN where none broke), which the DSMC's reader accepts.
TEST(OutcomeAggregates, FragmentMassConservedAndTableReadByTheDsmc) {
  const AggParsed p = parse_aggregates("speeds = [0.1, 3.0, 30.0]\nprimaries = [2]\nimpacts = 3\n");
  const test::AggregateImpacts r = test::run_aggregate_grid(p);
  const std::vector<PairOutcome> out = r.outcomes();
  std::vector<double> nf, fl;
  std::vector<std::vector<double>> fractions;
  for (std::size_t k = 0; k < r.fragments.size(); ++k) {
    const PairFragments& f = r.fragments[k];
    double total = 0.0;
    for (double x : r.masses[k]) total += x;
    EXPECT_NEAR(f.fragment_mass, total, 1e-14 * total);
    EXPECT_GE(f.largest_fraction, 1.0 / f.fragments);
    nf.push_back(f.fragments);
    fl.push_back(f.largest_fraction);
    double sum = 0.0;
    for (double x : f.fractions) sum += x;
    EXPECT_NEAR(sum, 1.0, 1e-14);  // the fragments' mass fractions
    EXPECT_EQ(f.fractions.size(), static_cast<std::size_t>(f.fragments));
    fractions.push_back(f.fractions);
  }
  const OutcomeGridResult t = tabulate_outcomes(p.grid, out, nf, fl);
  EXPECT_EQ(t.sticks[0], 3);  // 0.1 m/s sticks
  EXPECT_EQ(t.breaks[2], 3);  // 30 m/s breaks
  EXPECT_TRUE(std::isnan(t.fragments[0]));
  EXPECT_GE(t.fragments[2], 2.0);
  const auto table = acoustics::outcome_table_from_dataset(writers::outcomes_dataset(t, "test"));
  EXPECT_DOUBLE_EQ(table.axes[1][0], p.grid.diameters[0]);
  EXPECT_DOUBLE_EQ(table.p_break[2], 1.0);
  const auto fs = table.fragments_at(30.0, p.grid.diameters[0], p.grid.diameters[0]);
  EXPECT_DOUBLE_EQ(fs.number, t.fragments[2]);
  EXPECT_EQ(fs.bins, 0u);  // without the distribution: the (N_f, f_L) model
  // with it: the node's distribution, its numbers summing to N_f and its mass fractions to 1
  const OutcomeGridResult td = tabulate_outcomes(p.grid, out, nf, fl, fractions);
  const auto with = acoustics::outcome_table_from_dataset(writers::outcomes_dataset(td, "test"));
  const auto fb = with.fragments_at(30.0, p.grid.diameters[0], p.grid.diameters[0]);
  ASSERT_EQ(fb.bins, kFragmentFractionEdges.size() - 1);
  double n = 0.0, mu = 0.0;
  for (std::size_t b = 0; b < fb.bins; ++b) n += fb.bin_number[b], mu += fb.bin_mass[b];
  EXPECT_NEAR(n, t.fragments[2], 1e-12);
  EXPECT_NEAR(mu, 1.0, 1e-12);
}

// One node (1 m/s, 4 primaries, 1 um) of three impacts: the grid of the node-statistics tests below.
namespace {
OutcomeGridSpec one_node_three_impacts() {
  OutcomeGridSpec s;
  s.speeds = {1.0};
  s.primaries = {4};
  s.diameters = {1e-6};
  s.impacts = 3;
  return s;
}
}  // namespace

// The fragment mass distribution of a node: per bin of m / M the fragments' mean number and mass fraction
// over the breaks (0.25 in bin 5, 0.5 in bin 6, 0.75 in bin 7 of kFragmentFractionEdges); none when a break
// has no fractions (a journal of before them).
TEST(OutcomeAggregates, FragmentDistributionOverTheBreaks) {
  const OutcomeGridSpec s = one_node_three_impacts();
  const std::vector<PairOutcome> out = {PairOutcome::brk, PairOutcome::stick, PairOutcome::brk};
  auto t = tabulate_outcomes(s, out, {2.0, 1.0, 3.0}, {0.75, 1.0, 0.5}, {{0.25, 0.75}, {}, {0.5, 0.25, 0.25}});
  const std::size_t nb = kFragmentFractionEdges.size() - 1;
  ASSERT_EQ(t.fragment_number.size(), nb);
  const std::vector<double> number = {0, 0, 0, 0, 0, 1.5, 0.5, 0.5}, mass = {0, 0, 0, 0, 0, 0.375, 0.25, 0.375};
  EXPECT_EQ(t.fragment_number, number);
  EXPECT_EQ(t.fragment_mass, mass);
  EXPECT_EQ(fragment_fraction_bin(0.0), 0u);
  EXPECT_EQ(fragment_fraction_bin(1.0), nb - 1);
  t = tabulate_outcomes(s, out, {2.0, 1.0, 3.0}, {0.75, 1.0, 0.5}, {{0.25, 0.75}, {}, {}});
  EXPECT_TRUE(t.fragment_number.empty());
}

// The node means: over the breaks only; f_L raised to 1/N_f when below it by rounding only (five equal
// fragments: 0.2 computed as 0.19999999999999998), not when below it by more.
TEST(OutcomeAggregates, FragmentMeansOverTheBreaks) {
  const OutcomeGridSpec s = one_node_three_impacts();
  const std::vector<PairOutcome> out = {PairOutcome::brk, PairOutcome::stick, PairOutcome::brk};
  auto t = tabulate_outcomes(s, out, {5.0, 9.0, 5.0}, {0.19999999999999998, 0.9, 0.19999999999999998});
  EXPECT_EQ(t.fragments[0], 5.0);          // the stick's values are not read
  EXPECT_EQ(t.largest_fraction[0], 0.2);  // raised by the rounding error
  t = tabulate_outcomes(s, out, {5.0, 9.0, 5.0}, {0.19, 0.9, 0.19});
  EXPECT_EQ(t.largest_fraction[0], 0.19);  // a real violation is kept (and refused by the DSMC's reader)
}

// Charge axes with aggregate partners (docs/outcomes.md "Charge and permittivity"): each partner's charge
// sigma pi d^2 (d = 2 a N^(1/3)) spread evenly over its primaries, the permittivity on every primary; the
// DEM particles carry them (place_structure).
TEST(OutcomeAggregates, ChargeIsSpreadEvenlyOverThePrimaries) {
  const AggParsed p = parse_aggregates("speeds = [0.3]\nprimaries = [2, 4]\nimpacts = 1\n"
                                       "charges = [-5e-5, 2e-5]\npermittivities = [3.0]\n");
  for (const auto& j : outcome_impacts(p.grid)) {
    const ImpactCase c = outcome_case(p.dem, p.grid, j);
    const std::array<const AgglomerateSpec*, 2> partners = {&c.agglomerate, &c.projectile.body};
    const std::array<std::size_t, 2> sizes = {j.i1, j.i2}, charges = {j.c1, j.c2};
    for (std::size_t k = 0; k < 2; ++k) {
      const auto& s = partners[k]->structure;
      ASSERT_EQ(s.size(), static_cast<std::size_t>(p.grid.primaries[sizes[k]]));
      const double d = p.grid.diameters[sizes[k]], q = p.grid.charges[charges[k]] * constants::pi * d * d;
      double sum = 0.0;
      for (std::size_t i = 0; i < s.size(); ++i) {
        EXPECT_DOUBLE_EQ(s.charge[i], q / static_cast<double>(s.size()));
        EXPECT_EQ(s.permittivity[i], 3.0);
        sum += s.charge[i];
      }
      EXPECT_NEAR(sum, q, 1e-15 * std::abs(q));
    }
    EXPECT_TRUE(c.electrostatics);
  }
}
