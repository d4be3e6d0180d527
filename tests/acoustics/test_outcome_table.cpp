// The dry outcome table of the DSMC (outcomes.dry_model = "table", acoustics/outcome_table.hpp,
// docs/acoustics.md §1.7): interpolation, clamping, the file format, the refusals, and three engine
// checks against analytic or default results.
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/acoustics/outcomes.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/rng.hpp"
#include "agglo/io/netcdf_reader.hpp"
#include "helpers.hpp"
#include "outcome_table_helpers.hpp"

using namespace agglo;
using namespace agglo::acoustics;
namespace fs = std::filesystem;

namespace {

using test::log_axis;
using test::table_of;

fs::path write_table(const OutcomeTable& t, const std::string& name, io::Dataset* edit_source = nullptr) {
  return test::write_table_dataset(edit_source ? *edit_source : outcome_table_dataset(t), name);
}

// Multilinear in (ln v, ln d1, ln d2), within [0.05, 0.95] on the axes below.
double multilinear(double v, double d1, double d2) {
  const double x = std::log(v / 1e-3) / std::log(1e4), y = std::log(d1 / 1e-7) / std::log(1e3),
               z = std::log(d2 / 1e-7) / std::log(1e3);
  return 0.05 + 0.3 * x + 0.2 * y * z + 0.15 * x * y * (1 - z) + 0.1 * z * (1 - x);
}

}  // namespace

TEST(OutcomeTable, InterpolationIsExactOnMultilinearData) {
  // Non-uniform axes: nodes not equally spaced in log.
  const OutcomeTable t = table_of({1e-3, 2e-3, 3e-2, 0.5, 10.0}, {1e-7, 4e-7, 1e-6, 1e-4}, {1e-7, 3e-6, 1e-4},
                                  multilinear);
  CounterRng rng(7, 1, 2);
  for (int k = 0; k < 2000; ++k) {
    const double v = 1e-3 * std::pow(1e4, rng.uniform()), a = 1e-7 * std::pow(1e3, rng.uniform()),
                 b = 1e-7 * std::pow(1e3, rng.uniform());
    const OutcomeProbabilities p = t.at(v, a, b);
    EXPECT_NEAR(p.stick, multilinear(v, std::min(a, b), std::max(a, b)), 1e-12) << v << " " << a << " " << b;
    EXPECT_NEAR(p.stick + p.bounce + p.brk, 1.0, 1e-12);
    EXPECT_FALSE(p.clamped);
    EXPECT_EQ(p.stick, t.at(v, b, a).stick);  // the pair is queried as (smaller, larger)
  }
  // At a node the value is the node's.
  EXPECT_DOUBLE_EQ(t.at(3e-2, 4e-7, 3e-6).stick, t.p_stick[t.index(2, 1, 1)]);
}

TEST(OutcomeTable, QueriesOutsideAreClampedAndFlagged) {
  const OutcomeTable t = table_of({1e-3, 10.0}, {1e-7, 1e-4}, {1e-7, 1e-4}, multilinear);
  const OutcomeProbabilities low = t.at(1e-5, 1e-6, 2e-6), zero = t.at(0.0, 1e-6, 2e-6), high = t.at(100.0, 1e-6, 1e-3);
  EXPECT_TRUE(low.clamped);
  EXPECT_TRUE(zero.clamped);
  EXPECT_TRUE(high.clamped);
  EXPECT_NEAR(low.stick, multilinear(1e-3, 1e-6, 2e-6), 1e-12);
  EXPECT_NEAR(zero.stick, multilinear(1e-3, 1e-6, 2e-6), 1e-12);
  EXPECT_NEAR(high.stick, multilinear(10.0, 1e-6, 1e-4), 1e-12);
  EXPECT_FALSE(t.at(1e-3, 1e-7, 1e-4).clamped);  // on the end nodes: inside
  // Up to rounding (a diameter computed from a volume): still on the node; a 1e-6 relative step outside is not.
  EXPECT_FALSE(t.at(1e-3 * (1 - 1e-13), 1e-7 * (1 - 1e-13), 1e-4 * (1 + 1e-13)).clamped);
  EXPECT_TRUE(t.at(1e-3 * (1 - 1e-6), 1e-6, 2e-6).clamped);
  EXPECT_TRUE(t.at(1e-3, 1e-6, 1e-4 * (1 + 1e-6)).clamped);
  // One node along an axis: constant along it, any other value counts as outside.
  const OutcomeTable c = table_of({1.0}, {1e-6}, {1e-6}, [](double, double, double) { return 0.3; });
  EXPECT_DOUBLE_EQ(c.at(0.2, 1e-6, 1e-6).stick, 0.3);
  EXPECT_TRUE(c.at(0.2, 1e-6, 1e-6).clamped);
  EXPECT_FALSE(c.at(1.0, 1e-6, 1e-6).clamped);
  EXPECT_FALSE(c.at(1.0, 1e-6 * (1 + 1e-12), 1e-6).clamped);
}

TEST(OutcomeTable, FileRoundTripAndMalformedTables) {
  OutcomeTable t = table_of({1e-3, 0.1, 10.0}, {1e-7, 1e-4}, {1e-7, 1e-5, 1e-4}, multilinear);
  t.provenance = "test table";
  const OutcomeTable r = load_outcome_table(write_table(t, "roundtrip"));
  EXPECT_EQ(r.axes, t.axes);
  EXPECT_EQ(r.p_stick, t.p_stick);
  EXPECT_EQ(r.p_bounce, t.p_bounce);
  EXPECT_EQ(r.provenance, "test table");
  const auto refused = [&](const std::function<void(io::Dataset&)>& edit, const std::string& needle) {
    io::Dataset d = outcome_table_dataset(t);
    edit(d);
    try {
      (void)outcome_table_from_dataset(d);
      ADD_FAILURE() << "accepted; expected: " << needle;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  const auto var = [](io::Dataset& d, const char* n) -> io::Variable& {
    for (auto& v : d.variables)
      if (v.name == n) return v;
    throw std::logic_error(n);
  };
  refused([&](io::Dataset& d) { var(d, "speed").units = "cm s-1"; }, "variable 'speed' has units \"cm s-1\"");
  refused([&](io::Dataset& d) { var(d, "speed").reals[1] = 1e-4; }, "axis 'speed' is not strictly increasing");
  refused([&](io::Dataset& d) { var(d, "diameter_1").reals[0] = 0.0; }, "axis 'diameter_1' value 0 = 0");
  refused([&](io::Dataset& d) { var(d, "p_bounce").reals[3] += 0.01; }, "p_stick + p_bounce + p_break at node 3");
  refused([&](io::Dataset& d) { var(d, "p_stick").reals[2] = -0.1; }, "p_stick at node 2 = -0.1");
  refused([&](io::Dataset& d) { d.variables.pop_back(); }, "no variable 'p_break'");
  EXPECT_THROW(load_outcome_table(test::table_folder("missing") / "absent.nc"), io::NetcdfReadError);
}

namespace {

using test::kMonoN0;

std::string constant_case(std::uint64_t seed, const std::string& outcome_lines, double end) {
  return test::constant_kernel_case(seed, outcome_lines, end);
}

double mono_number_at_end(const std::string& toml) { return test::number_at_end(toml); }

using test::seed_mean_se;
using test::SeedMeanSe;

using test::constant_table_file;

}  // namespace

// Constant kernel K with P_stick = alpha: the effective kernel is alpha K, so
//   N(t) = N0 / (1 + alpha K N0 t / 2).
// 6 seeds of 4000 samples to tau = 2; the mean of N(2)/N_exact must lie within 3 standard errors of the
// seed mean (sigma from the seeds) plus 0.5 % (the method's bias at this step, measured: always_coalesce
// gives N/N_exact = 1.000 +- 0.001), and alpha applied twice (alpha^2) must be excluded.
TEST(OutcomeTable, ConstantKernelWithConstantStickProbability) {
  const double alpha = 0.5, tau = 2.0;
  const std::string table = constant_table_file(alpha, "alpha");
  std::vector<double> ratio;
  for (std::uint64_t seed = 1; seed <= 6; ++seed)
    ratio.push_back(mono_number_at_end(constant_case(seed, fmt::format("dry_model = \"table\"\ntable = \"{}\"", table), tau)) /
                    (kMonoN0 / (1.0 + alpha * tau / 2.0)));
  const SeedMeanSe r = seed_mean_se(ratio);
  std::printf("P_stick = %.2f: N/N_exact = %.5f +- %.5f (6 seeds)\n", alpha, r.mean, r.se);
  EXPECT_LT(std::abs(r.mean - 1.0), 3.0 * r.se + 0.005);
  // Negative control: alpha applied twice predicts N0 / (1 + alpha^2 tau / 2), 20 % more particles.
  const double twice = (1.0 + alpha * tau / 2.0) / (1.0 + alpha * alpha * tau / 2.0);
  EXPECT_GT(std::abs(r.mean / twice - 1.0), 3.0 * r.se / twice + 0.005);
}

// P_stick = 1 everywhere reproduces outcomes.always_coalesce: both against N0 / (1 + tau / 2) and each other.
TEST(OutcomeTable, StickProbabilityOneIsAlwaysCoalesce) {
  const double tau = 2.0;
  const std::string table = constant_table_file(1.0, "one");
  std::vector<double> with_table, always;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    with_table.push_back(mono_number_at_end(constant_case(seed, fmt::format("dry_model = \"table\"\ntable = \"{}\"", table), tau)) /
                         (kMonoN0 / (1.0 + tau / 2.0)));
    always.push_back(mono_number_at_end(constant_case(seed + 100, "always_coalesce = true", tau)) / (kMonoN0 / (1.0 + tau / 2.0)));
  }
  const SeedMeanSe a = seed_mean_se(with_table), b = seed_mean_se(always);
  std::printf("P_stick = 1: N/N_exact = %.5f +- %.5f; always_coalesce %.5f +- %.5f (4 seeds each)\n", a.mean, a.se,
              b.mean, b.se);
  EXPECT_LT(std::abs(a.mean - b.mean), 3.0 * std::hypot(a.se, b.se) + 1e-12);
  EXPECT_LT(std::abs(a.mean - 1.0), 3.0 * a.se + 0.005);
}

namespace {

// Solid spheres of 1 and 10 um (1e12 m^-3 each, 4000 samples each) in a 140 dB, 2 kHz wave with the
// constant kernel (K N t = 0.9 for the total N = 2e12 m^-3, over 100 steps of 1e-4 s): the 1-10 um pairs meet at normal speeds of 0-0.7 m/s
// around v_cr,dry(1 um, 10 um) = 0.19 m/s, the equal-size pairs well below it.
std::string two_size_case(std::uint64_t seed) { return test::two_size_wave_case(seed, 4000, 0.01, 4.5e-11, false); }

struct DryCounts {
  double stuck = 0, bounced = 0, queries = 0, clamped = 0;
};

DryCounts run_dry(EngineSettings s) {
  Engine e(std::move(s));
  while (e.time() < e.settings().t_end - 1e-9) e.step();
  const CollisionStats& st = e.stats();
  return {static_cast<double>(st.coalescences[1]), static_cast<double>(st.rebounds[1]),
          static_cast<double>(st.table_queries), static_cast<double>(st.table_clamped)};
}

}  // namespace

// A table of the closed-form critical velocity (P_stick = 1 at nodes with v <= v_cr,dry(d_1, d_2), else 0;
// 500 speeds over 1e-3-10 m/s, 20 diameters per decade over 0.5-40 um) reproduces the default dry outcome:
// the fraction of dry collisions that stick agrees within 3 binomial standard errors of the pooled counts
// of 3 seeds per model (the interpolation ramp spans 1.9 % of v_cr along the speed axis).
TEST(OutcomeTable, CriticalVelocityTableReproducesTheDefault) {
  const OutcomeParams oc;
  auto table = std::make_shared<OutcomeTable>(
      test::critical_velocity_table([&](double a, double b) { return critical_velocity_dry(oc, a, b, 2500.0, 2500.0); }));
  DryCounts def, tab;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    EngineSettings s = test::parse_case(two_size_case(seed)).engine;
    const DryCounts a = run_dry(s);
    s.outcomes.dry_model = OutcomeModel::table;
    s.outcomes.dry_table = table;
    s.seed += 1000;
    const DryCounts b = run_dry(s);
    def.stuck += a.stuck, def.bounced += a.bounced;
    tab.stuck += b.stuck, tab.bounced += b.bounced, tab.queries += b.queries, tab.clamped += b.clamped;
  }
  const double nd = def.stuck + def.bounced, nt = tab.stuck + tab.bounced;
  const double fd = def.stuck / nd, ft = tab.stuck / nt;
  const double se = std::sqrt(fd * (1 - fd) / nd + ft * (1 - ft) / nt);
  std::printf("dry stick fraction: critical velocity %.4f (%.0f collisions), table %.4f (%.0f; %.0f clamped), "
              "s.e. of the difference %.4f\n", fd, nd, ft, nt, tab.clamped, se);
  ASSERT_GT(def.bounced, 500.0);  // both outcomes occur often
  ASSERT_GT(def.stuck, 500.0);
  EXPECT_EQ(tab.queries, nt);
  EXPECT_LT(std::abs(fd - ft), 3.0 * se);
}

// The case file selects the table; refusals name outcomes.table with the reason.
TEST(OutcomeTable, CaseFileSelectsAndRefuses) {
  const std::string good = constant_table_file(0.5, "case");
  const std::string base = constant_case(1, "", 0.1);
  const auto with = [&](const std::string& lines) { return constant_case(1, lines, 0.1); };
  AcousticCase c = test::parse_case(with(fmt::format("dry_model = \"table\"\ntable = \"{}\"", good)));
  ASSERT_EQ(c.engine.outcomes.dry_model, OutcomeModel::table);
  EXPECT_DOUBLE_EQ(c.engine.outcomes.dry_table->at(0.1, 1e-6, 1e-6).stick, 0.5);
  EXPECT_EQ(test::parse_case(base).engine.outcomes.dry_model, OutcomeModel::critical_velocity);
  const auto refused = test::expect_case_refused;
  OutcomeTable brk = table_of({1e-3, 10.0}, {1e-7, 1e-4}, {1e-7, 1e-4}, [](double, double, double) { return 0.5; });
  brk.p_bounce.assign(brk.p_bounce.size(), 0.3);
  brk.p_break.assign(brk.p_break.size(), 0.2);
  const std::string breaking = write_table(brk, "break").string();
  refused(fmt::format("dry_model = \"table\"\ntable = \"{}\"", breaking),
          "key 'outcomes.table' = \"" + breaking + "\": not an outcome table (docs/acoustics.md §1.7): p_break at node 0 "
          "= 0.2 > 0, but no variable 'fragments'");
  refused("dry_model = \"table\"", "key 'outcomes.table'");
  refused(fmt::format("table = \"{}\"", good), "is read only with outcomes.dry_model = \"table\"");
  refused("dry_model = \"table\"\ntable = \"/nonexistent/t.nc\"", "cannot read /nonexistent/t.nc");
  refused("dry_model = \"tables\"", "outcomes.dry_model");
}
