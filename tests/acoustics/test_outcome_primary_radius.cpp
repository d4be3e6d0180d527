// Primary-radius axes of the dry outcome table (acoustics/outcome_table.hpp: `primary_radius_1`,
// `primary_radius_2` [m], log space, after the other axes): multilinear data in (ln v, ln d_1, ln d_2, ln a_1,
// ln a_2) interpolated exactly, the partners' radii following their diameters, clamping outside the axes
// flagged, the round trip, one axis alone refused, and the radius a sample is queried with (its primary
// radius; d_v / 2 for a compact sphere).
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/core/rng.hpp"

using namespace agglo;
using namespace agglo::acoustics;

namespace {

// A multilinear function of the logarithms (a product term in ln v ln a_1 and one in ln d_2 ln a_2), scaled
// into [0.05, 0.95] over the table below.
double radius_table_value(double v, double d1, double d2, double a1, double a2) {
  const double lv = std::log(v / 0.05), l1 = std::log(d1 / 1e-6), l2 = std::log(d2 / 1e-6);
  const double la1 = std::log(a1 / 1e-8), la2 = std::log(a2 / 1e-8);
  return 0.05 + 0.01 * (lv + 2.0 * l1 - l2 + 1.5 * la1 + 0.5 * la2 + 0.3 * lv * la1 + 0.2 * l2 * la2);
}

// 3 speeds x 3 x 3 diameters x 3 x 4 primary radii (non-uniform), P_stick from the function above.
OutcomeTable radius_table() {
  OutcomeTable t;
  t.axes[kSpeedAxis] = {0.05, 0.3, 2.0};
  t.axes[kDiameter1Axis] = {1e-6, 2.5e-6, 1e-5};
  t.axes[kDiameter2Axis] = {1e-6, 4e-6, 1e-5};
  t.axes[kPrimaryRadius1Axis] = {1e-8, 3e-8, 1e-7};
  t.axes[kPrimaryRadius2Axis] = {1e-8, 2e-8, 5e-8, 1e-7};
  for (double v : t.axes[kSpeedAxis])
    for (double d1 : t.axes[kDiameter1Axis])
      for (double d2 : t.axes[kDiameter2Axis])
        for (double a1 : t.axes[kPrimaryRadius1Axis])
          for (double a2 : t.axes[kPrimaryRadius2Axis]) {
            const double p = radius_table_value(v, d1, d2, a1, a2);
            t.p_stick.push_back(p);
            t.p_bounce.push_back(1.0 - p);
            t.p_break.push_back(0.0);
          }
  return t;
}

double log_uniform(CounterRng& rng, double lo, double hi) { return lo * std::exp(rng.uniform() * std::log(hi / lo)); }

}  // namespace

// 2000 random queries inside the axes: P_stick equals the multilinear function to 1e-12, also with the
// partners named the other way round (the radii go with the diameters), and none is flagged.
TEST(OutcomePrimaryRadius, MultilinearDataInterpolatedExactly) {
  const OutcomeTable t = outcome_table_from_dataset(outcome_table_dataset(radius_table()));
  ASSERT_TRUE(t.has_primary_radii());
  CounterRng rng(41, 2, 3);
  double worst = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const double v = log_uniform(rng, 0.05, 2.0), d1 = log_uniform(rng, 1e-6, 1e-5), d2 = log_uniform(rng, 1e-6, 1e-5);
    const double a1 = log_uniform(rng, 1e-8, 1e-7), a2 = log_uniform(rng, 1e-8, 1e-7);
    // the smaller diameter is partner 1 of the table, with its own primary radius
    const double expect = d1 <= d2 ? radius_table_value(v, d1, d2, a1, a2) : radius_table_value(v, d2, d1, a2, a1);
    OutcomeQuery q{v, d1, d2};
    q.rp_i = a1, q.rp_j = a2;
    const OutcomeProbabilities p = t.at(q);
    std::swap(q.d_i, q.d_j);
    std::swap(q.rp_i, q.rp_j);
    const OutcomeProbabilities s = t.at(q);
    worst = std::max({worst, std::abs(p.stick - expect), std::abs(s.stick - expect)});
    EXPECT_FALSE(p.clamped || s.clamped);
  }
  EXPECT_LT(worst, 1e-12);
  // Negative control: the radii not swapped with the diameters miss the function.
  OutcomeQuery q{0.3, 1e-5, 1e-6};
  q.rp_i = 1e-8, q.rp_j = 1e-7;
  EXPECT_GT(std::abs(t.at(q).stick - radius_table_value(0.3, 1e-6, 1e-5, 1e-8, 1e-7)), 0.01);
}

// Outside a primary-radius axis: the end node's value, flagged; the pair at rest of a 3-axis table reads
// the radii not at all.
TEST(OutcomePrimaryRadius, ClampedOutsideAndFlagged) {
  const OutcomeTable t = radius_table();
  OutcomeQuery q{0.3, 1e-6, 1e-5};
  q.rp_i = 5e-9, q.rp_j = 1e-7;
  const OutcomeProbabilities p = t.at(q);
  EXPECT_TRUE(p.clamped);
  EXPECT_NEAR(p.stick, radius_table_value(0.3, 1e-6, 1e-5, 1e-8, 1e-7), 1e-12);
  q.rp_i = 1e-8, q.rp_j = 2e-7;
  EXPECT_TRUE(t.at(q).clamped);
  OutcomeTable three;
  three.axes = {std::vector<double>{0.1, 1.0}, std::vector<double>{1e-6}, std::vector<double>{1e-6}};
  three.p_stick = {0.2, 0.4};
  three.p_bounce = {0.8, 0.6};
  three.p_break = {0.0, 0.0};
  q = OutcomeQuery{0.1, 1e-6, 1e-6};
  q.rp_i = 1.0;  // not read
  EXPECT_FALSE(three.at(q).clamped);
  EXPECT_FALSE(outcome_table_from_dataset(outcome_table_dataset(three)).has_primary_radii());
}

// One primary-radius axis alone, a non-positive or decreasing radius: refused with the reason.
TEST(OutcomePrimaryRadius, MalformedAxesRefused) {
  OutcomeTable t = radius_table();
  t.axes[kPrimaryRadius2Axis].clear();
  t.p_stick.resize(t.nodes()), t.p_bounce.resize(t.nodes()), t.p_break.resize(t.nodes());
  EXPECT_THROW((void)outcome_table_from_dataset(outcome_table_dataset(t)), std::invalid_argument);
  t = radius_table();
  t.axes[kPrimaryRadius1Axis][0] = 0.0;
  EXPECT_THROW((void)outcome_table_from_dataset(outcome_table_dataset(t)), std::invalid_argument);
  t = radius_table();
  t.axes[kPrimaryRadius2Axis][2] = 1.5e-8;
  EXPECT_THROW((void)outcome_table_from_dataset(outcome_table_dataset(t)), std::invalid_argument);
}

// The radius a sample is queried with: its primary radius when it is an aggregate, d_v / 2 for a compact
// sample (a sphere is one primary).
TEST(OutcomePrimaryRadius, SamplesQueryTheirPrimaryRadius) {
  const Gas gas = Gas::air(298.15, 101325.0, true);
  const Sound snd = Sound::make(gas, true, 147.0, 1400.0);
  SampleSet compact;
  const double v = 4.0 / 3.0 * 3.141592653589793 * 1e-18;  // d_v = 2 um
  compact.add(0, 0, 0, v, 0.0, 2500.0 * v, 1.0, 0, gas, snd);
  EXPECT_NEAR(compact.query_primary_radius(0), 1e-6, 1e-18);
  SampleSet agg;
  StructureLaw law;
  law.fractal = true;
  law.primary_radius = 2e-8;
  law.fractal_dimension = 1.8;
  law.fractal_prefactor = 1.3;
  agg.structure_laws = {law};
  agg.add(0, 0, 0, v, 0.0, 2500.0 * v, 1.0, 0, gas, snd);
  agg.set_primaries(0, 2e-8, gas, snd);
  EXPECT_EQ(agg.query_primary_radius(0), 2e-8);
}
