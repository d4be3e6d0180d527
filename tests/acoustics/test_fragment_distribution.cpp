// The fragment mass distribution of the dry outcome table (acoustics/outcome_table.hpp: per bin of m / M the
// mean number h_b and mass fraction mu_b of the fragments of one broken pair) and the DSMC's breakage by it
// (acoustics/fragments.hpp): mass and momentum exact per event, the drawn fragments per bin (number and mass)
// against W h_b and W mu_b M with a stated number of standard errors, and the negative control of a draw
// by number instead of mass share; the interpolation between nodes, the file round trip, tables without the
// distribution read as before, and malformed distributions refused.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agglo/acoustics/fragments.hpp"
#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/core/rng.hpp"
#include "outcome_table_helpers.hpp"

using namespace agglo;
using namespace agglo::acoustics;

namespace {

// Four bins of m / M, with h_b and mu_b chosen so that every mean fraction mu_b / h_b (0.05, 0.2, 0.45,
// 0.7) lies inside its bin: N_f = 3 + 1 + 0.5 + 0.425 / 0.7 = 5.107.
const std::vector<double> kDistEdges = {0.0, 0.1, 0.3, 0.6, 1.0};
const std::array<double, 4> kDistNumber = {3.0, 1.0, 0.5, 0.425 / 0.7};
const std::array<double, 4> kDistMass = {0.15, 0.2, 0.225, 0.425};

FragmentStats dist_stats(const std::array<double, 4>& number, const std::array<double, 4>& mass) {
  FragmentStats f;
  f.bins = 4;
  f.number = 0.0;
  for (std::size_t b = 0; b < 4; ++b) {
    f.bin_number[b] = number[b];
    f.bin_mass[b] = mass[b];
    f.number += number[b];
  }
  return f;
}

std::size_t dist_bin(double f) {
  std::size_t b = 0;
  while (b + 2 < kDistEdges.size() && f >= kDistEdges[b + 1]) ++b;
  return b;
}

// Per bin over the events: mean and standard error of the fragments' number and mass (in units of W M).
struct DistTally {
  std::array<double, 4> n{}, n2{}, m{}, m2{};
  double events = 0.0, worst_mass = 0.0, worst_momentum = 0.0;
  double se(double s, double s2) const { return std::sqrt((s2 / events - (s / events) * (s / events)) / (events - 1.0)); }
};

// `events` breaks of a pair of weights wi, wj by f; the fragments are binned by their mass fraction.
DistTally dist_breaks(double wi, double wj, const FragmentStats& f, int events, std::uint64_t seed) {
  const Gas gas;
  const Sound sound;
  DistTally t;
  CounterRng rng(seed, 41, 1);
  for (int e = 0; e < events; ++e) {
    SampleSet p = test::pair_of_samples(wi, wj, gas, sound);
    const double W = std::min(wi, wj), M = p.mass[0] + p.mass[1];
    std::array<double, 3> mom0{}, mom{};
    double scale = 0.0;  // W sum m |v|, the scale of the momentum's rounding
    for (std::size_t k = 0; k < 2; ++k) {
      const std::array<double, 3> v = {p.vx[k], p.vy[k], p.vz[k]};
      for (std::size_t a = 0; a < 3; ++a) mom0[a] += W * p.mass[k] * v[a];
      scale += W * p.mass[k] * std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    break_weighted(p, 0, 1, f, rng, gas, sound);
    std::array<double, 4> n{}, m{};
    double mass = 0.0;
    for (std::size_t k = 0; k < 2; ++k) {
      if (wi != wj && k == (wi > wj ? 0u : 1u)) continue;  // the heavier sample keeps its state (w_h - W)
      n[dist_bin(p.mass[k] / M)] += p.w[k];
      m[dist_bin(p.mass[k] / M)] += p.w[k] * p.mass[k] / (W * M);
      mass += p.w[k] * p.mass[k];
      const std::array<double, 3> v = {p.vx[k], p.vy[k], p.vz[k]};
      for (std::size_t a = 0; a < 3; ++a) mom[a] += p.w[k] * p.mass[k] * v[a];
    }
    t.worst_mass = std::max(t.worst_mass, std::abs(mass - W * M) / (W * M));
    for (std::size_t a = 0; a < 3; ++a) t.worst_momentum = std::max(t.worst_momentum, std::abs(mom[a] - mom0[a]) / scale);
    for (std::size_t b = 0; b < 4; ++b) {
      t.n[b] += n[b], t.n2[b] += n[b] * n[b], t.m[b] += m[b], t.m2[b] += m[b] * m[b];
    }
    t.events += 1.0;
  }
  return t;
}

// The largest |z| over the bins of the number (against W h_b) and of the mass share (against mu_b).
double dist_worst_z(const DistTally& t, double W) {
  double z = 0.0;
  for (std::size_t b = 0; b < 4; ++b) {
    z = std::max(z, std::abs(t.n[b] / t.events - W * kDistNumber[b]) / t.se(t.n[b], t.n2[b]));
    z = std::max(z, std::abs(t.m[b] / t.events - kDistMass[b]) / t.se(t.m[b], t.m2[b]));
  }
  return z;
}

// A 2-speed x 1 x 1 table with P_break = 0.2 and 0.6, the distribution of each node given.
OutcomeTable dist_table(const std::array<double, 4>& n0, const std::array<double, 4>& m0,
                        const std::array<double, 4>& n1, const std::array<double, 4>& m1) {
  OutcomeTable t;
  t.axes[kSpeedAxis] = {0.1, 10.0};
  t.axes[kDiameter1Axis] = {1e-6};
  t.axes[kDiameter2Axis] = {1e-6};
  t.p_stick = {0.5, 0.2};
  t.p_bounce = {0.3, 0.2};
  t.p_break = {0.2, 0.6};
  t.fragment_edges = kDistEdges;
  t.fragment_number.assign(n0.begin(), n0.end());
  t.fragment_number.insert(t.fragment_number.end(), n1.begin(), n1.end());
  t.fragment_mass.assign(m0.begin(), m0.end());
  t.fragment_mass.insert(t.fragment_mass.end(), m1.begin(), m1.end());
  return t;
}

}  // namespace

// 20 000 breaks each of equal weights (8, 8) and unequal ones (9, 4): the fragments per bin follow the table,
// number W h_b and mass mu_b W M, every bin within 4 standard errors (16 comparisons per weight pair; seeds
// 7 and 8); mass and momentum per event to 1e-15. Negative control: the bins drawn in proportion to h_b
// (by number) instead of mu_b put the number off by more than 20 standard errors.
TEST(FragmentDistribution, DrawnFragmentsFollowTheTable) {
  const FragmentStats f = dist_stats(kDistNumber, kDistMass);
  for (const auto& [wi, wj, seed] : {std::array<double, 3>{8.0, 8.0, 7.0}, std::array<double, 3>{9.0, 4.0, 8.0}}) {
    const DistTally t = dist_breaks(wi, wj, f, 20000, static_cast<std::uint64_t>(seed));
    EXPECT_LT(dist_worst_z(t, std::min(wi, wj)), 4.0) << wi << " " << wj;
    EXPECT_LT(t.worst_mass, 1e-15);
    EXPECT_LT(t.worst_momentum, 1e-15);
    std::array<double, 4> by_number{};  // the wrong rule: the class drawn with probability h_b / N_f
    for (std::size_t b = 0; b < 4; ++b) by_number[b] = kDistNumber[b] / f.number;
    FragmentStats wrong = dist_stats(kDistNumber, by_number);
    for (std::size_t b = 0; b < 4; ++b) wrong.bin_number[b] = kDistNumber[b] / kDistMass[b] * by_number[b];
    const DistTally c = dist_breaks(wi, wj, wrong, 20000, static_cast<std::uint64_t>(seed));
    EXPECT_GT(dist_worst_z(c, std::min(wi, wj)), 20.0) << wi << " " << wj;
    std::printf("weights %g, %g: largest |z| %.2f (control %.1f); mass %.2g, momentum %.2g\n", wi, wj,
                dist_worst_z(t, std::min(wi, wj)), dist_worst_z(c, std::min(wi, wj)), t.worst_mass, t.worst_momentum);
  }
}

// Between nodes: h_b and mu_b are the means weighted by W_c P_break,c (a node without breaks, NaN, ignored).
TEST(FragmentDistribution, InterpolatedWithTheBreakWeights) {
  const std::array<double, 4> n1 = {0.0, 2.0, 1.0, 0.0}, m1 = {0.0, 0.5, 0.5, 0.0};
  OutcomeTable t = dist_table(kDistNumber, kDistMass, n1, m1);
  const FragmentStats f = t.fragments_at(1.0, 1e-6, 1e-6);  // ln-midpoint: corner weights 1/2, 1/2
  ASSERT_EQ(f.bins, 4u);
  double n = 0.0;
  for (std::size_t b = 0; b < 4; ++b) {
    EXPECT_NEAR(f.bin_number[b], (0.2 * kDistNumber[b] + 0.6 * n1[b]) / 0.8, 1e-12);
    EXPECT_NEAR(f.bin_mass[b], (0.2 * kDistMass[b] + 0.6 * m1[b]) / 0.8, 1e-12);
    n += f.bin_number[b];
  }
  EXPECT_NEAR(f.number, n, 1e-12);
  t.p_stick[0] = 0.7, t.p_break[0] = 0.0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::fill(t.fragment_number.begin(), t.fragment_number.begin() + 4, nan);
  const FragmentStats g = outcome_table_from_dataset(outcome_table_dataset(t)).fragments_at(0.5, 1e-6, 1e-6);
  for (std::size_t b = 0; b < 4; ++b) EXPECT_DOUBLE_EQ(g.bin_number[b], n1[b]);
}

// The variables round-trip; a table without them reads as before (bins = 0: the (N_f, f_L) model).
TEST(FragmentDistribution, RoundTripAndTablesWithoutIt) {
  const OutcomeTable t = dist_table(kDistNumber, kDistMass, kDistNumber, kDistMass);
  const io::Dataset d = outcome_table_dataset(t);
  ASSERT_NE(d.find(kFragmentDistribution[0]), nullptr);
  EXPECT_EQ(d.find(kFragmentDistribution[0])->dims.back(), kFragmentBinDim);
  const OutcomeTable r = outcome_table_from_dataset(d);
  EXPECT_EQ(r.fragment_edges, kDistEdges);
  EXPECT_EQ(r.fragment_number, t.fragment_number);
  EXPECT_EQ(r.fragment_mass, t.fragment_mass);
  OutcomeTable old = t;
  old.fragment_edges.clear(), old.fragment_number.clear(), old.fragment_mass.clear();
  old.fragments = {3.0, 4.0};
  old.largest_fraction = {0.5, 0.4};
  const OutcomeTable o = outcome_table_from_dataset(outcome_table_dataset(old));
  EXPECT_EQ(o.fragment_bins(), 0u);
  const FragmentStats f = o.fragments_at(0.1, 1e-6, 1e-6);
  EXPECT_EQ(f.bins, 0u);
  EXPECT_DOUBLE_EQ(f.number, 3.0);
  EXPECT_DOUBLE_EQ(f.largest, 0.5);
}

// Refused with their reason: mass fractions not summing to 1, a mean fraction outside its bin, a number
// without mass, fewer than 2 fragments, edges not from 0 to 1, a sum of h_b other than `fragments`.
TEST(FragmentDistribution, MalformedDistributionsAreRefused) {
  const auto refused = [](const OutcomeTable& t, const std::string& why) {
    try {
      (void)outcome_table_from_dataset(outcome_table_dataset(t));
      ADD_FAILURE() << "accepted: " << why;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  const OutcomeTable good = dist_table(kDistNumber, kDistMass, kDistNumber, kDistMass);
  OutcomeTable t = good;
  t.fragment_mass[5] = 0.3;
  refused(t, "instead of 1");
  t = good;
  t.fragment_number[2] = 0.3;  // mean fraction 0.225 / 0.3 = 0.75 outside [0.3, 0.6]
  refused(t, "outside its bin");
  t = good;
  t.fragment_mass[0] = 0.0, t.fragment_mass[1] = 0.35;
  refused(t, "zero together");
  t = dist_table({0.0, 0.0, 1.0, 0.6}, {0.0, 0.0, 0.55, 0.45}, kDistNumber, kDistMass);
  refused(t, "at least 2 fragments");
  t = good;
  t.fragment_edges.back() = 0.9;
  refused(t, "run from 0 to 1");
  t = good;
  t.fragments = {5.0, 5.0};
  t.largest_fraction = {0.5, 0.5};
  refused(t, "but fragments");
}
