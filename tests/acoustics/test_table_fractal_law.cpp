// A fractal population taking D_f and k_f from the dry outcome table (population.fractal_law = "table",
// docs/acoustics.md §1.8; the table's attributes fractal_dimension, fractal_prefactor of outcome_table.hpp):
// the samples' collision radii follow the table's law, the attributes round-trip and are checked, and a run
// without a table or with a table without a law is refused naming the key.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/core/error.hpp"
#include "helpers.hpp"
#include "outcome_table_helpers.hpp"

using namespace agglo::acoustics;

namespace {

// A one-node table (P_stick = 1), with the fractal law (D_f, k_f) when df > 0.
OutcomeTable one_node_law_table(double df, double kf) {
  OutcomeTable t;
  t.axes[kSpeedAxis] = {1.0};
  t.axes[kDiameter1Axis] = {1e-7};
  t.axes[kDiameter2Axis] = {1e-7};
  t.p_stick = {1.0};
  t.p_bounce = {0.0};
  t.p_break = {0.0};
  if (df > 0.0) {
    t.fractal_dimension = df;
    t.fractal_prefactor = kf;
    t.fractal_law = "test";
  }
  return t;
}

// Fractal soot (25 nm primaries, lognormal around 0.2 um) in the coagulation box with the dry outcome table
// `table`; `law` holds the population's law keys.
std::string law_box(const std::string& table, const std::string& law) {
  return std::string(test::kCoagulationBox) + test::constant_kernel_steps("1e-4") +
         (table.empty() ? std::string() : "[outcomes]\ndry_model = \"table\"\ntable = \"" + table + "\"\n") +
         test::soot_population(200, "2.5e-8") + law;
}

}  // namespace

// Every sample's collision diameter is 2 max(r_v, r_p (n_p / k_f)^(1/D_f)) with the table's D_f = 1.7,
// k_f = 1.4 (to 1e-12); the law given by hand (1.8, 1.3: negative control) misses most samples by > 5 %.
TEST(TableFractalLaw, SamplesFollowTheTablesLaw) {
  const std::string file = test::write_table_dataset(outcome_table_dataset(one_node_law_table(1.7, 1.4)), "law").string();
  const Engine e = test::make_engine(law_box(file, "fractal_law = \"table\"\n"));
  EXPECT_EQ(e.settings().populations.at(0).structure.fractal_dimension, 1.7);
  EXPECT_EQ(e.settings().populations.at(0).structure.fractal_prefactor, 1.4);
  const SampleSet& p = e.particles();
  ASSERT_TRUE(p.structured());
  std::size_t missed_by_hand = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double rv = 0.5 * p.volume_diameter(i), rp = p.rp[i];
    const double table_law = 2.0 * std::max(rv, rp * std::pow(p.np[i] / 1.4, 1.0 / 1.7));
    const double by_hand = 2.0 * std::max(rv, rp * std::pow(p.np[i] / 1.3, 1.0 / 1.8));
    EXPECT_NEAR(p.d[i], table_law, 1e-12 * table_law) << i;
    missed_by_hand += std::abs(p.d[i] / by_hand - 1.0) > 0.05;
  }
  EXPECT_GT(missed_by_hand, p.size() / 2);
}

TEST(TableFractalLaw, AttributesRoundTripAndAreChecked) {
  const OutcomeTable t =
      load_outcome_table(test::write_table_dataset(outcome_table_dataset(one_node_law_table(1.7, 1.4)), "law_rt"));
  EXPECT_EQ(t.fractal_dimension, 1.7);
  EXPECT_EQ(t.fractal_prefactor, 1.4);
  EXPECT_EQ(t.fractal_law, "test");
  agglo::io::Dataset d = outcome_table_dataset(one_node_law_table(1.7, 1.4));
  d.attributes[kFractalDimensionAttribute] = 3.5;  // D_f > 3
  EXPECT_THROW(outcome_table_from_dataset(d), std::invalid_argument);
  d.attributes.erase(kFractalDimensionAttribute);  // k_f alone
  EXPECT_THROW(outcome_table_from_dataset(d), std::invalid_argument);
  EXPECT_FALSE(outcome_table_from_dataset(outcome_table_dataset(one_node_law_table(0.0, 0.0))).has_fractal_law());
}

// Refused naming population.fractal_law: a table without the law, no table; and D_f given besides.
TEST(TableFractalLaw, RefusedWithoutATableLaw) {
  const std::string bare = test::write_table_dataset(outcome_table_dataset(one_node_law_table(0.0, 0.0)), "nolaw").string();
  for (const std::string& table : {bare, std::string()}) {
    try {
      test::parse_case(law_box(table, "fractal_law = \"table\"\n"));
      FAIL() << "accepted without a table law: " << table;
    } catch (const agglo::ConfigError& err) {
      const std::string w = err.what();  // key 'population.0.fractal_law'
      EXPECT_NE(w.find("population.0.fractal_law"), std::string::npos) << w;
    }
  }
  const std::string with = test::write_table_dataset(outcome_table_dataset(one_node_law_table(1.7, 1.4)), "law2").string();
  EXPECT_THROW(test::parse_case(law_box(with, "fractal_law = \"table\"\nfractal_dimension = 1.8\n")), agglo::ConfigError);
  EXPECT_NO_THROW(test::parse_case(law_box(with, "fractal_law = \"given\"\nfractal_dimension = 1.8\nfractal_prefactor = 1.3\n")));
}
