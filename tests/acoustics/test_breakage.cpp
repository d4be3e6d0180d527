// Breakage in the DSMC (acoustics/fragments.hpp, the dry outcome table's P_break and fragment statistics,
// outcome_table.hpp): the weighted rule conserves mass and momentum exactly and the number in expectation,
// a run with P_break = 1 follows the analytic number, the table's fragment statistics are read, checked and
// interpolated, and tables with P_break = 0 give the results of the code before breakage.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "agglo/acoustics/fragments.hpp"
#include "agglo/acoustics/merge.hpp"
#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/core/error.hpp"
#include "helpers.hpp"
#include "outcome_table_helpers.hpp"

using namespace agglo;
using namespace agglo::acoustics;
namespace fs = std::filesystem;

namespace {

// A table over 2 speeds x 2 x 2 diameters (1e-9 .. 1e-3 m: fragments of micrometre spheres stay inside)
// with constant P_stick, P_break (P_bounce = the rest) and constant fragment statistics.
using test::constant_break_table;
using test::pair_of_samples;

double total_mass(const SampleSet& p) {
  double m = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) m += p.w[i] * p.mass[i];
  return m;
}

// sum w m |v| (the scale of the momentum's rounding)
double momentum_scale(const SampleSet& p) {
  double s = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    s += p.w[i] * p.mass[i] * std::sqrt(p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i] + p.vz[i] * p.vz[i]);
  return s;
}

}  // namespace

// Equal weights: the largest fragments on i (weight W, mass f_L M), the others on j (weight R(W (N_f - 1)),
// together (1 - f_L) W M); all at the centre-of-mass velocity; mass and momentum to rounding.
TEST(Breakage, EqualWeightsGiveTheLargestAndTheOtherFragments) {
  const Gas gas;
  const Sound sound;
  const FragmentStats f{3.3, 0.45};
  CounterRng rng(11, 2, 3);
  for (int k = 0; k < 200; ++k) {
    SampleSet p = pair_of_samples(8.0, 8.0, gas, sound);
    const Merged m = merged_state(p, 0, 1);
    const double mass0 = total_mass(p), scale = momentum_scale(p);
    const Vec3 mom0 = momentum(p);
    break_weighted(p, 0, 1, f, rng, gas, sound);
    EXPECT_EQ(p.w[0], 8.0);
    EXPECT_TRUE(p.w[1] == 18.0 || p.w[1] == 19.0) << p.w[1];  // R(8 x 2.3 = 18.4)
    EXPECT_NEAR(p.mass[0], 0.45 * m.mass, 1e-15 * m.mass);
    EXPECT_NEAR(p.w[1] * p.mass[1], 8.0 * 0.55 * m.mass, 1e-14 * m.mass);
    EXPECT_NEAR(total_mass(p), mass0, 1e-15 * mass0);
    EXPECT_LT(norm(momentum(p) - mom0), 1e-15 * scale);
    for (std::size_t s = 0; s < 2; ++s) {
      EXPECT_EQ(p.vx[s], m.v.x);
      EXPECT_NEAR(p.rho[s], m.mass / (m.vol_s + m.vol_l), 1e-12 * p.rho[s]);  // density of the pair kept
    }
  }
  // A weight that is not a whole number (never made by the samplers) takes the real count, unrounded.
  SampleSet p = pair_of_samples(0.5, 0.5, gas, sound);
  const double mass0 = total_mass(p);
  break_weighted(p, 0, 1, f, rng, gas, sound);
  EXPECT_EQ(p.w[0], 0.5);
  EXPECT_DOUBLE_EQ(p.w[1], 0.5 * 2.3);
  EXPECT_NEAR(total_mass(p), mass0, 1e-15 * mass0);
}

// Unequal weights: the heavier sample keeps w_h - w_l; the lighter becomes one fragment class. Over many
// events the fragment number W N_f is reproduced (mean within 4 standard errors), which a class drawn with
// probability 1/2 instead of its mass share (the negative control, mean 9.60 instead of 9.90) is not.
TEST(Breakage, UnequalWeightsReproduceTheFragmentNumberInTheMean) {
  const Gas gas;
  const Sound sound;
  const FragmentStats f{3.3, 0.45};
  const double W = 3.0, expected = W * f.number;
  const double control = 0.5 * W / f.largest + 0.5 * W * (f.number - 1.0) / (1.0 - f.largest);
  CounterRng rng(5, 7, 9);
  const int n = 20000;
  double s = 0.0, s2 = 0.0, largest_mass = 0.0, all_mass = 0.0;
  for (int k = 0; k < n; ++k) {
    SampleSet p = pair_of_samples(7.0, W, gas, sound);
    const double mass0 = total_mass(p), scale = momentum_scale(p), M = p.mass[0] + p.mass[1], m0 = p.mass[0];
    const Vec3 mom0 = momentum(p);
    break_weighted(p, 0, 1, f, rng, gas, sound);
    ASSERT_EQ(p.w[0], 4.0);
    ASSERT_EQ(p.mass[0], m0);  // untouched
    ASSERT_EQ(p.vx[0], 0.3);
    ASSERT_NEAR(total_mass(p), mass0, 1e-15 * mass0);
    ASSERT_LT(norm(momentum(p) - mom0), 1e-15 * scale);
    s += p.w[1];
    s2 += p.w[1] * p.w[1];
    all_mass += W * M;
    if (p.mass[1] > 0.3 * M) largest_mass += W * M;  // the largest class (f_L M = 0.45 M, rounded)
  }
  const double mean = s / n, se = std::sqrt((s2 / n - mean * mean) / (n - 1));
  std::printf("fragments per event: %.4f +- %.4f (expected %.2f, control %.2f); mass share of the largest %.4f\n",
              mean, se, expected, control, largest_mass / all_mass);
  EXPECT_LT(std::abs(mean - expected), 4.0 * se);
  EXPECT_GT(std::abs(mean - control), 4.0 * se);
  EXPECT_NEAR(largest_mass / all_mass, f.largest, 4.0 * std::sqrt(f.largest * (1 - f.largest) / n));
}

// Fragment statistics between nodes: the means given a break, weighted by P_break (nodes without breaks
// do not count, even when they hold NaN).
TEST(Breakage, FragmentStatisticsAreConditionalMeans) {
  OutcomeTable t = constant_break_table(0.2, 0.4, {3.0, 0.5});
  // Speed nodes 1e-4 (index 0) and 100 (index 1): no breaks at the slow node, P_break = 0.4 or 0.8 at the fast.
  for (std::size_t i1 = 0; i1 < 2; ++i1)
    for (std::size_t i2 = 0; i2 < 2; ++i2) {
      const std::size_t slow = t.index(0, i1, i2);
      t.p_break[slow] = 0.0;
      t.p_bounce[slow] = 0.8;
      t.fragments[slow] = std::nan("");
      t.largest_fraction[slow] = std::nan("");
    }
  const double v = std::sqrt(1e-4 * 100.0);  // halfway in ln v
  EXPECT_DOUBLE_EQ(t.fragments_at(v, 1e-6, 2e-6).number, 3.0);
  EXPECT_DOUBLE_EQ(t.fragments_at(v, 1e-6, 2e-6).largest, 0.5);
  // Two broken corners with P_break 0.4 (N_f = 3, f_L = 0.5) and 0.8 (N_f = 6, f_L = 0.25), halfway:
  //   N_f = (0.4 x 3 + 0.8 x 6) / 1.2 = 5, f_L = (0.4 x 0.5 + 0.8 x 0.25) / 1.2 = 1/3.
  OutcomeTable u = constant_break_table(0.2, 0.4, {3.0, 0.5});
  for (std::size_t i1 = 0; i1 < 2; ++i1)
    for (std::size_t i2 = 0; i2 < 2; ++i2) {
      const std::size_t fast = u.index(1, i1, i2);
      u.p_break[fast] = 0.8;
      u.p_bounce[fast] = 0.0;
      u.fragments[fast] = 6.0;
      u.largest_fraction[fast] = 0.25;
    }
  EXPECT_NEAR(u.fragments_at(v, 1e-6, 2e-6).number, 5.0, 1e-12);
  EXPECT_NEAR(u.fragments_at(v, 1e-6, 2e-6).largest, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(u.at(v, 1e-6, 2e-6).brk, 0.6, 1e-12);
}

namespace {

fs::path breakage_table_file(const OutcomeTable& t, const std::string& name) {
  return test::write_table_dataset(outcome_table_dataset(t), "breakage_" + name);
}

using test::kMonoN0;

// The constant-kernel box (outcome_table_helpers.hpp) with the dry outcome table `table`.
std::string breakage_case(std::uint64_t seed, const std::string& table, double end) {
  return test::constant_kernel_case(seed, fmt::format("dry_model = \"table\"\ntable = \"{}\"", table), end);
}

void run_to_end(Engine& e) {
  while (e.time() < e.settings().t_end - 1e-9) e.step();
}

}  // namespace

// Constant kernel K, every collision breaks into N_f fragments: a collision of two real particles adds
// N_f - 2, so dN/dt = (N_f - 2) K N^2 / 2 and N(t) = N0 / (1 - (N_f - 2) K N0 t / 2). N_f = 2.5 to tau = 1
// (N = 4/3 N0): 8 seeds of 4000 samples; the seed mean of N/N_exact within 3 standard errors (from the seeds)
// plus 0.5 % (the method's bias at this step, as for coalescence, test_outcome_table.cpp), and the
// prediction with 4 % more fragments per break, N_f = 2.6 (N = 1.43 N0, the negative control), excluded.
// Mass and momentum of every run are those at the start to rounding. The samples get velocities (the box
// has no gas motion, and integrator = "none" leaves them), so that the momentum is not trivially 0.
TEST(Breakage, NumberFollowsTheFragmentNumberAndMassAndMomentumAreConserved) {
  const double nf = 2.5, tau = 1.0;
  const std::string table = breakage_table_file(constant_break_table(0.0, 1.0, {nf, 0.6}), "all").string();
  std::vector<double> ratio;
  double mass_err = 0.0, mom_err = 0.0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    Engine e = test::make_engine(breakage_case(seed, table, tau));
    SampleSet& p = e.particles();
    CounterRng vel(seed, 77, 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.vx[i] = vel.uniform() - 0.3;
      p.vy[i] = vel.uniform() - 0.5;
      p.vz[i] = 2.0 * vel.uniform();
    }
    const double mass0 = total_mass(p), scale = momentum_scale(p);
    const Vec3 mom0 = momentum(p);
    run_to_end(e);
    const CollisionStats& st = e.stats();
    ASSERT_GT(st.breakups[static_cast<int>(PairType::dry)], 1000u);
    EXPECT_EQ(st.breakups[static_cast<int>(PairType::dry)], st.collisions);
    EXPECT_EQ(st.coalescences[static_cast<int>(PairType::dry)] + st.rebounds[static_cast<int>(PairType::dry)], 0u);
    EXPECT_EQ(p.size(), 4000u);  // the sample count stays
    mass_err = std::max(mass_err, std::abs(total_mass(p) - mass0) / mass0);
    mom_err = std::max(mom_err, norm(momentum(p) - mom0) / scale);
    ratio.push_back(test::total_number(p) / (kMonoN0 / (1.0 - (nf - 2.0) * tau / 2.0)));
  }
  const test::SeedMeanSe r = test::seed_mean_se(ratio);
  const double m = r.mean, se = r.se;
  const double control = (1.0 - (nf - 2.0) * tau / 2.0) / (1.0 - (nf + 0.1 - 2.0) * tau / 2.0);  // N_f = 2.6
  std::printf("N_f = %.1f: N/N_exact = %.5f +- %.5f (8 seeds); N_f = 2.6 predicts %.4f; largest relative change "
              "of mass %.2e, of momentum %.2e (of sum w m |v|)\n", nf, m, se, control, mass_err, mom_err);
  EXPECT_LT(mass_err, 1e-12);
  EXPECT_LT(mom_err, 1e-12);
  EXPECT_LT(std::abs(m - 1.0), 3.0 * se + 0.005);
  EXPECT_GT(std::abs(m - control), 3.0 * se + 0.005);
}

// The case file accepts a table with P_break > 0 and fragment statistics; it refuses one without them, or
// with N_f < 2, f_L outside [1/N_f, 1) or P_break outside [0, 1], naming outcomes.table and the variable.
TEST(Breakage, CaseFileAcceptsBreakageAndRefusesBadStatistics) {
  const auto parse = [](const fs::path& t) { return test::parse_case(breakage_case(1, t.string(), 0.1)); };
  const AcousticCase c = parse(breakage_table_file(constant_break_table(0.5, 0.2, {4.0, 0.5}), "good"));
  EXPECT_NEAR(c.engine.outcomes.dry_table->at(1.0, 1e-6, 1e-6).brk, 0.2, 1e-15);
  EXPECT_EQ(c.engine.outcomes.dry_table->fragments_at(1.0, 1e-6, 1e-6).number, 4.0);
  const auto refused = [&](OutcomeTable t, const std::string& name, const std::string& needle) {
    const fs::path f = breakage_table_file(t, name);
    try {
      (void)parse(f);
      ADD_FAILURE() << "accepted: " << name;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("key 'outcomes.table'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  OutcomeTable none = constant_break_table(0.5, 0.2, {4.0, 0.5});
  none.fragments.clear();
  none.largest_fraction.clear();
  refused(none, "none", "p_break at node 0 = 0.2 > 0, but no variable 'fragments'");
  refused(constant_break_table(0.5, 0.2, {1.5, 0.8}), "few", "fragments at node 0 = 1.5 where p_break > 0");
  refused(constant_break_table(0.5, 0.2, {4.0, 0.2}), "small", "largest_fraction at node 0 = 0.2 where p_break > 0");
  refused(constant_break_table(0.5, 0.2, {4.0, 1.0}), "whole", "largest_fraction at node 0 = 1 where p_break > 0");
  OutcomeTable big = constant_break_table(0.0, 1.0, {4.0, 0.5});
  big.p_break[3] = 1.5;
  refused(big, "big", "p_break at node 3 = 1.5 is outside [0, 1]");
}

namespace {

// Solid spheres of 1 and 10 um (1000 samples each) in a 140 dB, 2 kHz wave, 100 cells, 30 steps of 1e-4 s,
// constant kernel: dry pairs meet at 0-0.7 m/s.
std::string zero_break_case() { return test::two_size_wave_case(3, 1000, 0.003, 3e-10, true); }

// FNV-1a over the bytes of the samples' state and the outcome counters.
std::uint64_t state_hash(const Engine& e) {
  std::uint64_t h = 1469598103934665603ULL;
  const auto add = [&](const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k) h = (h ^ b[k]) * 1099511628211ULL;
  };
  const SampleSet& p = e.particles();
  for (const auto* v : {&p.x, &p.y, &p.z, &p.vx, &p.vy, &p.vz, &p.vol_s, &p.mass, &p.w, &p.debt})
    add(v->data(), v->size() * sizeof(double));
  const CollisionStats& st = e.stats();
  add(st.coalescences, sizeof st.coalescences);
  add(st.rebounds, sizeof st.rebounds);
  return h;
}

}  // namespace

// Regression: a table with P_break = 0 (P_stick falling linearly in ln v from 1 at 0.02 m/s to 0 at 0.5 m/s)
// gives, bit for bit, the samples and counters of the code before breakage (commit 2e09281, where this
// hash was recorded with this test), as does a table that also holds fragment statistics.
TEST(Breakage, ZeroBreakTableGivesTheResultsOfTheCodeBeforeBreakage) {
  auto table = std::make_shared<OutcomeTable>();
  table->axes = {std::vector<double>{0.02, 0.5}, std::vector<double>{1e-7, 1e-4}, std::vector<double>{1e-7, 1e-4}};
  table->p_stick = {1, 1, 1, 1, 0, 0, 0, 0};
  table->p_bounce = {0, 0, 0, 0, 1, 1, 1, 1};
  table->p_break.assign(8, 0.0);
  EngineSettings s = test::parse_case(zero_break_case()).engine;
  s.outcomes.dry_model = OutcomeModel::table;
  s.outcomes.dry_table = table;
  Engine e(s);
  run_to_end(e);
  const std::uint64_t h = state_hash(e);
  // The same table with fragment statistics (not read where P_break = 0).
  auto with_stats = std::make_shared<OutcomeTable>(*table);
  with_stats->fragments.assign(8, 3.0);
  with_stats->largest_fraction.assign(8, 0.5);
  s.outcomes.dry_table = with_stats;
  Engine e2(s);
  run_to_end(e2);
  EXPECT_EQ(state_hash(e2), h);
  std::printf("state hash %016llx; dry: %llu stuck, %llu bounced\n", static_cast<unsigned long long>(h),
              static_cast<unsigned long long>(e.stats().coalescences[1]),
              static_cast<unsigned long long>(e.stats().rebounds[1]));
  EXPECT_GT(e.stats().coalescences[1], 50u);
  EXPECT_GT(e.stats().rebounds[1], 50u);
  EXPECT_EQ(h, 0x93276178146a4c2fULL);
}
