// Charge and permittivity in the DSMC's dry outcome table (acoustics/outcome_table.hpp, docs/acoustics.md
// §1.7): multilinear lookup over all six axes, the 3-axis files of before, the refusals, and the charge of
// the samples (samples.hpp): summed on merging, shared by mass on breaking, conserved over a run.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "agglo/acoustics/fragments.hpp"
#include "agglo/acoustics/merge.hpp"
#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/rng.hpp"
#include "helpers.hpp"
#include "outcome_table_helpers.hpp"

using namespace agglo;
using namespace agglo::acoustics;

namespace {

using Axes = std::array<std::vector<double>, kOutcomeAxisCount>;

// A table over `axes` (absent: empty) with P_stick = f(node coordinates), P_bounce = 1 - P_stick.
OutcomeTable charged_table_of(const Axes& axes, const std::function<double(const std::array<double, 6>&)>& f) {
  OutcomeTable t;
  t.axes = axes;
  std::array<std::size_t, kOutcomeAxisCount> n{};
  for (std::size_t k = 0; k < kOutcomeAxisCount; ++k) n[k] = axes[k].empty() ? 1 : axes[k].size();
  std::array<std::size_t, kOutcomeAxisCount> i{};
  for (i[0] = 0; i[0] < n[0]; ++i[0])
    for (i[1] = 0; i[1] < n[1]; ++i[1])
      for (i[2] = 0; i[2] < n[2]; ++i[2])
        for (i[3] = 0; i[3] < n[3]; ++i[3])
          for (i[4] = 0; i[4] < n[4]; ++i[4])
            for (i[5] = 0; i[5] < n[5]; ++i[5]) {
              std::array<double, 6> x{};
              for (std::size_t k = 0; k < x.size(); ++k)  // absent: uncharged, kappa_p = 1
                x[k] = axes[k].empty() ? (k == kPermittivityAxis ? 1.0 : 0.0) : axes[k][i[k]];
              t.p_stick.push_back(f(x));
              t.p_bounce.push_back(1.0 - t.p_stick.back());
              t.p_break.push_back(0.0);
            }
  return t;
}

// Multilinear in (ln v, ln d1, ln d2, sigma1, sigma2, ln kappa), within [0, 1] on the axes below.
double six_linear(const std::array<double, 6>& x) {
  const double v = std::log(x[0] / 1e-2) / std::log(1e3), a = std::log(x[1] / 1e-7) / std::log(1e3),
               b = std::log(x[2] / 1e-7) / std::log(1e3), s1 = (x[3] + 1e-4) / 2e-4, s2 = (x[4] + 1e-4) / 2e-4,
               k = std::log(x[5]) / std::log(10.0);
  return 0.05 + 0.15 * v * a + 0.1 * b * s1 + 0.2 * s1 * s2 * (1 - k) + 0.1 * k * v + 0.15 * s2 * (1 - a) * b +
         0.1 * v * s1 * k;
}

const Axes kSixAxes = {std::vector<double>{1e-2, 0.1, 2.0, 10.0}, {1e-7, 1e-6, 1e-4}, {1e-7, 3e-6, 1e-4},
                       {-1e-4, -2e-5, 0.0, 1e-4}, {-1e-4, 5e-5, 1e-4}, {1.0, 3.0, 10.0}};

}  // namespace

TEST(OutcomeCharge, InterpolationIsExactOnDataLinearInEveryAxis) {
  const OutcomeTable t = charged_table_of(kSixAxes, six_linear);
  CounterRng rng(3, 1, 4);
  for (int k = 0; k < 2000; ++k) {
    OutcomeQuery q{1e-2 * std::pow(1e3, rng.uniform()), 1e-7 * std::pow(1e3, rng.uniform()),
                   1e-7 * std::pow(1e3, rng.uniform()), -1e-4 + 2e-4 * rng.uniform(), -1e-4 + 2e-4 * rng.uniform(),
                   std::pow(10.0, rng.uniform())};
    const bool swap = q.d_j < q.d_i;  // partner 1 is the smaller, its charge with it
    const std::array<double, 6> x = {q.speed,       std::min(q.d_i, q.d_j), std::max(q.d_i, q.d_j),
                                     swap ? q.sigma_j : q.sigma_i, swap ? q.sigma_i : q.sigma_j, q.permittivity};
    const OutcomeProbabilities p = t.at(q);
    EXPECT_NEAR(p.stick, six_linear(x), 1e-12);
    EXPECT_FALSE(p.clamped);
    const OutcomeQuery r{q.speed, q.d_j, q.d_i, q.sigma_j, q.sigma_i, q.permittivity};
    EXPECT_EQ(t.at(r).stick, p.stick);  // the same pair named the other way round
  }
  // Signed charges: below, above and at the ends of a charge axis (linear: relative to the axis' span).
  const OutcomeQuery in{1.0, 1e-6, 2e-6, -1e-4, 1e-4, 2.0};
  EXPECT_FALSE(t.at(in).clamped);
  OutcomeQuery out = in;
  out.sigma_i = -1.1e-4;
  EXPECT_TRUE(t.at(out).clamped);
  EXPECT_DOUBLE_EQ(t.at(out).stick, t.at(in).stick);
  out = in;
  out.sigma_j = 1e-4 + 1e-18;  // within 1e-9 of the span: on the node
  EXPECT_FALSE(t.at(out).clamped);
  out.permittivity = 20.0;
  EXPECT_TRUE(t.at(out).clamped);
}

// A table of only the three old axes is the file format of before: written and read as it was, and
// queries with charges or permittivity read it as the uncharged table (an absent axis is not read).
TEST(OutcomeCharge, ThreeAxisFilesReadUnchanged) {
  const Axes three = {std::vector<double>{1e-2, 10.0}, {1e-7, 1e-4}, {1e-7, 1e-4}, {}, {}, {}};
  const OutcomeTable t = charged_table_of(three, six_linear);
  const io::Dataset d = outcome_table_dataset(t);
  std::vector<std::string> names;
  for (const auto& v : d.variables) names.push_back(v.name);
  EXPECT_EQ(names, (std::vector<std::string>{"speed", "diameter_1", "diameter_2", "p_stick", "p_bounce", "p_break"}));
  EXPECT_EQ(d.find("p_stick")->dims, (std::vector<std::string>{"speed", "diameter_1", "diameter_2"}));
  const OutcomeTable r = load_outcome_table(test::write_table_dataset(d, "three_axes"));
  EXPECT_FALSE(r.charged());
  EXPECT_FALSE(r.has_axis(kPermittivityAxis));
  EXPECT_EQ(r.axes, t.axes);
  EXPECT_EQ(r.p_stick, t.p_stick);
  const OutcomeQuery q{0.3, 1e-6, 2e-6, 5e-5, -3e-5, 4.0};
  EXPECT_EQ(r.at(q).stick, r.at(0.3, 1e-6, 2e-6).stick);
  EXPECT_FALSE(r.at(q).clamped);
  // The six-axis table round-trips through its file.
  const OutcomeTable six = charged_table_of(kSixAxes, six_linear);
  const OutcomeTable s = load_outcome_table(test::write_table_dataset(outcome_table_dataset(six), "six_axes"));
  EXPECT_EQ(s.axes, six.axes);
  EXPECT_EQ(s.p_stick, six.p_stick);
}

TEST(OutcomeCharge, MalformedChargeAxesAreRefused) {
  const auto refused = [](Axes axes, const std::string& needle) {
    try {
      (void)outcome_table_from_dataset(outcome_table_dataset(charged_table_of(axes, six_linear)));
      ADD_FAILURE() << "accepted; expected: " << needle;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  Axes one = kSixAxes;
  one[kCharge2Axis].clear();
  refused(one, "axis 'charge_1' without axis 'charge_2'");
  Axes bad = kSixAxes;
  bad[kPermittivityAxis] = {0.0, 2.0};
  refused(bad, "axis 'permittivity' value 0 = 0 is not a positive number");
  bad = kSixAxes;
  bad[kCharge1Axis] = {1e-5, -1e-5};
  refused(bad, "axis 'charge_1' is not strictly increasing");
}

namespace {

// Two solid samples of 1 and 2 um with charges qi, qj [C] and weights wi, wj.
SampleSet charged_pair(double wi, double wj, double qi, double qj, const Gas& gas, const Sound& sound) {
  SampleSet p;
  p.carries_charge = true;
  const double vi = 1e-18 * constants::pi / 6.0, vj = 8.0 * vi;
  p.add(0, 0, 0, vi, 0.0, 2500.0 * vi, wi, 0, gas, sound);
  p.add(0, 0, 0, vj, 0.0, 2500.0 * vj, wj, 0, gas, sound);
  p.q = {qi, qj};
  p.vx = {0.3, -0.1};
  return p;
}

double total_charge(const SampleSet& p) {
  double q = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) q += p.w[i] * p.q[i];
  return q;
}

}  // namespace

// Merging sums the charges, breaking shares them by mass: sum w q is conserved to rounding for equal (odd,
// even) and unequal weights. Negative control: the charge sigma pi d^2 that a constant surface density
// would give the merged particle is not the sum.
TEST(OutcomeCharge, MergingAndBreakingConserveCharge) {
  const Gas gas;
  const Sound sound;
  const double qi = 3e-17, qj = -1.1e-16;
  CounterRng rng(2, 7, 1);
  for (const auto& w : std::vector<std::array<double, 2>>{{5, 5}, {4, 4}, {7, 3}, {2, 9}}) {
    SampleSet p = charged_pair(w[0], w[1], qi, qj, gas, sound);
    const double q0 = total_charge(p);
    coalesce_weighted(p, 0, 1, gas, sound);
    EXPECT_NEAR(total_charge(p), q0, 1e-15 * std::abs(q0)) << w[0] << " " << w[1];
    const std::size_t merged = w[0] >= w[1] ? 1 : 0;
    EXPECT_DOUBLE_EQ(p.q[merged], qi + qj);
    SampleSet b = charged_pair(w[0], w[1], qi, qj, gas, sound);
    const Merged m = merged_state(b, 0, 1);
    const std::array<double, 2> mass0 = {b.mass[0], b.mass[1]};
    break_weighted(b, 0, 1, FragmentStats{3.4, 0.5}, rng, gas, sound);
    EXPECT_NEAR(total_charge(b), q0, 1e-15 * std::abs(q0)) << w[0] << " " << w[1];
    for (std::size_t k = 0; k < 2; ++k)  // every fragment carries the pair's charge per mass
      if (b.mass[k] != mass0[k]) {
        EXPECT_NEAR(b.q[k] / b.mass[k], m.charge / m.mass, 1e-12 * std::abs(m.charge / m.mass));
      }
  }
  // Negative control: sigma pi d^2 of the merged 9^(1/3) um particle, sigma of the 1 um one, is not q_i + q_j.
  const double sigma = qi / (constants::pi * 1e-12), d = 1e-6 * std::cbrt(9.0);
  EXPECT_GT(std::abs(sigma * constants::pi * d * d - (qi + qj)), 0.5 * std::abs(qi + qj));
}

// A run with a charged population and a charged table (P_stick 0.3, P_break 0.3, N_f = 3, f_L = 0.5): the
// total charge sum w q is conserved to rounding while particles merge and break (both counted); the
// negative control, the charge sigma pi d_v^2 that the population's constant sigma would give at the end,
// is not. A charged population without a charged table is refused.
TEST(OutcomeCharge, RunConservesChargeAndChargedPopulationsNeedAChargedTable) {
  Axes axes = {std::vector<double>{1e-4, 100.0}, {1e-9, 1e-3}, {1e-9, 1e-3}, {-1e-3, 1e-3}, {-1e-3, 1e-3}, {}};
  OutcomeTable t = charged_table_of(axes, [](const std::array<double, 6>&) { return 0.3; });
  for (auto& b : t.p_bounce) b = 0.4;
  t.p_break.assign(t.p_stick.size(), 0.3);
  t.fragments.assign(t.p_stick.size(), 3.0);
  t.largest_fraction.assign(t.p_stick.size(), 0.5);
  const std::string file = test::write_table_dataset(outcome_table_dataset(t), "charged_run").string();
  std::string toml = test::constant_kernel_case(1, fmt::format("dry_model = \"table\"\ntable = \"{}\"", file), 0.5);
  const std::string sigma_line = "charge_density = 2e-5\n";
  toml.replace(toml.find("samples = 4000\n"), 15, "samples = 4000\n" + sigma_line);
  Engine e = test::make_engine(toml);
  const auto sums = [&] {
    double q = 0.0, s = 0.0;
    for (std::size_t i = 0; i < e.particles().size(); ++i) {
      const double d = e.particles().volume_diameter(i);
      q += e.particles().w[i] * e.particles().q[i];
      s += e.particles().w[i] * 2e-5 * constants::pi * d * d;
    }
    return std::array<double, 2>{q, s};
  };
  const auto start = sums();
  EXPECT_NEAR(start[0], start[1], 1e-12 * start[1]);
  while (e.time() < e.settings().t_end - 1e-9) e.step();
  const auto end = sums();
  std::printf("charge: start %.10g C, end %.10g C; sigma pi d^2 at the end %.10g C; %llu merges, %llu breaks\n",
              start[0], end[0], end[1], static_cast<unsigned long long>(e.stats().coalescences[1]),
              static_cast<unsigned long long>(e.stats().breakups[1]));
  EXPECT_GT(e.stats().coalescences[1], 100u);
  EXPECT_GT(e.stats().breakups[1], 100u);
  EXPECT_NEAR(end[0], start[0], 1e-12 * start[0]);
  EXPECT_GT(std::abs(end[1] - start[0]), 1e-3 * start[0]);
  // Without a charged table the population's charge would do nothing: refused, naming the key.
  std::string plain = test::constant_kernel_case(1, "", 0.5);
  plain.replace(plain.find("samples = 4000\n"), 15, "samples = 4000\n" + sigma_line);
  EXPECT_THROW(test::parse_case(plain), ConfigError);
}
