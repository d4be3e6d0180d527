// Outputs a user needs (issue 26 item 4): PM1/PM2.5/PM10 mass by volume-equivalent and aerodynamic
// diameter (acoustics/diagnostics.hpp) against hand computations, and the collisions that stuck,
// bounced and broke by pair type (outcomes_by_pair.csv, writers/acoustic.hpp): they add up to the
// collision count of efficiency.csv, and are the same after a restart and at any thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "agglo/acoustics/checkpoint.hpp"
#include "agglo/acoustics/diagnostics.hpp"
#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/acoustics/run.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/writers/acoustic.hpp"
#include "helpers.hpp"

namespace agglo::acoustics {
namespace {

Gas room_air() { return Gas::air(293.15, 101325.0, false); }

// d_a by bisection on rho_0 d^2 C_c(d) = rho_p d_v^2 C_c(d_v) (a different method than the fixed point).
double aerodynamic_by_bisection(const Gas& g, double dv, double rho) {
  const double target = rho * dv * dv * g.slip_correction(dv);
  double lo = 1e-9, hi = 1e-2;
  for (int it = 0; it < 200; ++it) {
    const double mid = std::sqrt(lo * hi);
    (kPmUnitDensity * mid * mid * g.slip_correction(mid) < target ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

TEST(PmMass, AerodynamicDiameterOfA2umSphereOfDensity2500) {
  const Gas g = room_air();
  const double da = aerodynamic_diameter(g, 2e-6, 2500.0);
  EXPECT_NEAR(da / aerodynamic_by_bisection(g, 2e-6, 2500.0), 1.0, 1e-12);
  // Hand value: d_v sqrt(2.5) = 3.162 um, raised by sqrt(C_c(2 um) / C_c(3.2 um)) = sqrt(1.083 / 1.052): 3.21 um.
  EXPECT_NEAR(da, 3.21e-6, 0.01e-6);
  // Without slip the formula is d_v sqrt(rho_p / rho_0); slip makes d_a larger for rho_p > rho_0.
  EXPECT_GT(da, 2e-6 * std::sqrt(2.5));
}

TEST(PmMass, AerodynamicDiameterLimits) {
  const Gas g = room_air();
  // Large spheres: C_c -> 1, d_a -> d_v sqrt(rho_p / rho_0).
  EXPECT_NEAR(aerodynamic_diameter(g, 1e-3, 2500.0) / (1e-3 * std::sqrt(2.5)), 1.0, 1e-4);
  // Unit density: d_a = d_v at any size.
  for (double d : {0.05e-6, 0.5e-6, 5e-6}) EXPECT_NEAR(aerodynamic_diameter(g, d, 1000.0) / d, 1.0, 1e-12);
  // Sub-micrometre: the bisection agrees where slip is large.
  EXPECT_NEAR(aerodynamic_diameter(g, 0.1e-6, 2500.0) / aerodynamic_by_bisection(g, 0.1e-6, 2500.0), 1.0, 1e-12);
}

// Solid spheres of density 2500 kg/m^3 in a 2 m^3 box: d [m] and weight.
struct Hand {
  double d, w;
};

TEST(PmMass, HandMadeSamplesAgainstAHandComputation) {
  const Gas g = room_air();
  const Sound s = Sound::make(g, false, 140.0, 2000.0);
  const double rho = 2500.0, V = 2.0;
  // 0.5 um (d_a 0.83 um), 2 um (3.2 um), 2.5 um exactly (a sharp cut: not PM2.5), 5 um (7.9 um), 20 um,
  // and a dead sample of 0.5 um (weight 0: counts nothing).
  const Hand hand[] = {{0.5e-6, 3e6}, {2e-6, 2e5}, {2.5e-6, 1e5}, {5e-6, 4e4}, {20e-6, 1e3}, {0.5e-6, 0.0}};
  SampleSet p;
  for (const Hand& h : hand) {
    const double v = constants::pi / 6.0 * h.d * h.d * h.d;
    p.add(0.1, 0.1, 0.1, v, 0.0, rho * v, h.w, 0, g, s);
  }
  const auto m = [&](const Hand& h) { return h.w * rho * constants::pi / 6.0 * h.d * h.d * h.d / V; };
  const PmMass pm = pm_mass(p, V, g);
  // Volume-equivalent: PM1 = {0.5}, PM2.5 = {0.5, 2}, PM10 = {0.5, 2, 2.5, 5}.
  EXPECT_NEAR(pm.volume[0] / m(hand[0]), 1.0, 1e-12);
  EXPECT_NEAR(pm.volume[1] / (m(hand[0]) + m(hand[1])), 1.0, 1e-12);
  EXPECT_NEAR(pm.volume[2] / (m(hand[0]) + m(hand[1]) + m(hand[2]) + m(hand[3])), 1.0, 1e-12);
  // Aerodynamic: PM1 = {0.5}, PM2.5 = {0.5} (2 um is 3.2 um aerodynamic), PM10 = {0.5, 2, 2.5, 5}.
  EXPECT_NEAR(pm.aerodynamic[0] / m(hand[0]), 1.0, 1e-12);
  EXPECT_NEAR(pm.aerodynamic[1] / m(hand[0]), 1.0, 1e-12);
  EXPECT_NEAR(pm.aerodynamic[2] / pm.volume[2], 1.0, 1e-12);
  // The classification agrees with aerodynamic_diameter sample by sample.
  for (std::size_t k = 0; k < 3; ++k) {
    double sum = 0.0;
    for (const Hand& h : hand) sum += aerodynamic_diameter(g, h.d, rho) < kPmCuts[k] ? m(h) : 0.0;
    EXPECT_NEAR(pm.aerodynamic[k], sum, 1e-12 * sum) << kPmNames[k];
  }
  // Negative control: the aerodynamic PM2.5 is not the volume-equivalent one here.
  EXPECT_LT(pm.aerodynamic[1], 0.9 * pm.volume[1]);
  EXPECT_DOUBLE_EQ(pm_reduction(2.0, 0.5), 0.75);
  EXPECT_DOUBLE_EQ(pm_reduction(0.0, 0.0), 0.0);
}

// Solid fines and water droplets in a standing wave (droplet pairs; mixed particles make wet pairs),
// 4200 samples (above the engine's threshold for a parallel step), 60 steps.
std::string pair_case(int seed = 5) {
  return test::standing_wave_case({seed, 1.0e-6, 2e13, 4000, 2e11, 200}, R"(
[output]
efficiency_interval = 2e-4
psd_times = [0.0]
)");
}

std::string csv_of(const io::Table& t) {
  std::ostringstream os;
  t.write_csv(os);
  return os.str();
}

const io::Table& table(const std::vector<io::Table>& ts, const std::string& file) {
  for (const auto& t : ts)
    if (t.file() == file) return t;
  throw std::runtime_error("no table " + file);
}

const io::Column& column(const io::Table& t, const std::string& name) {
  for (const auto& c : t.columns())
    if (c.name == name) return c;
  throw std::runtime_error("no column " + name);
}

AcousticObservations run_case(const AcousticCase& c, int threads, const std::string* resume = nullptr,
                              std::string* checkpoint = nullptr) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  RunHooks h;
  h.checkpoint_interval = checkpoint ? 7.5e-4 : 0.0;  // the first at step 30
  if (checkpoint) h.checkpoint = [&](std::uint64_t, double, const std::string& b) {
    if (checkpoint->empty()) *checkpoint = b;
  };
  std::optional<io::CheckpointReader> reader;
  if (resume) reader.emplace(*resume, "test checkpoint");
  h.resume = reader ? &*reader : nullptr;
  AcousticObservations o = run_acoustic(c, h);
  omp_set_num_threads(before);
  return o;
}

TEST(OutcomesByPair, CountsAddUpToTheCollisionsAndFractionsToOne) {
  const AcousticCase c = test::parse_case(pair_case());
  const AcousticObservations o = run_case(c, 2);
  const auto ts = writers::acoustic_tables(o);
  const io::Table& t = table(ts, "outcomes_by_pair.csv");
  const auto& n = column(t, "pair_collisions").ints;
  const auto& stuck = column(t, "stuck").ints;
  const auto& bounced = column(t, "bounced").ints;
  const auto& broke = column(t, "broke").ints;
  ASSERT_EQ(n.size(), 3u);
  std::int64_t total = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(n[k], stuck[k] + bounced[k] + broke[k]);
    EXPECT_EQ(broke[k], 0) << "no breakage without an outcome table";
    total += n[k];
  }
  ASSERT_GT(n[0], 100) << "droplet pairs: a case without them would test little";
  EXPECT_EQ(stuck[0], n[0]) << "a pure droplet always coalesces";
  EXPECT_EQ(static_cast<std::uint64_t>(total), o.stats.collisions);
  EXPECT_EQ(static_cast<std::uint64_t>(total), o.efficiency.back().collisions);  // efficiency.csv's count
  const auto& fs = column(t, "stuck_fraction").reals;
  const auto& fb = column(t, "bounced_fraction").reals;
  for (std::size_t k = 0; k < 3; ++k) {
    if (n[k] == 0) {
      EXPECT_EQ(fs[k] + fb[k], 0.0) << "finite outputs: 0 without collisions";
      continue;
    }
    EXPECT_NEAR(fs[k] + fb[k] + column(t, "broke_fraction").reals[k], 1.0, 1e-12);
  }
  EXPECT_NE(o.log.find("outcomes by pair type"), std::string::npos);
  // PM: agglomeration conserves mass (PM10 by volume stays, as no particle grows past 10 um... in 60 steps
  // droplets of 30 um hold most mass anyway) and removes fines: PM1 falls.
  const io::Table& e = table(ts, "efficiency.csv");
  const auto& r1 = column(e, "pm1_vol_reduction").reals;
  EXPECT_EQ(r1.front(), 0.0);
  EXPECT_GT(r1.back(), 0.0);
  EXPECT_NE(o.log.find("PM mass"), std::string::npos);
}

// With a dry outcome table of P_break = 0.5 (fragment statistics N_f = 3, f_L = 0.5) the dry pairs break:
// the counts reach outcomes_by_pair.csv (and so results.nc) and run.log, still add up, and are the same
// at any thread count and after a restart.
TEST(OutcomesByPair, DryBreakagesAreCounted) {
  AcousticCase c = test::parse_case(pair_case());
  auto t = std::make_shared<OutcomeTable>();
  t->axes = {std::vector<double>{1e-4, 100.0}, std::vector<double>{1e-9, 1e-3}, std::vector<double>{1e-9, 1e-3}};
  t->p_stick.assign(8, 0.3);
  t->p_bounce.assign(8, 0.2);
  t->p_break.assign(8, 0.5);
  t->fragments.assign(8, 3.0);
  t->largest_fraction.assign(8, 0.5);
  c.engine.outcomes.dry_model = OutcomeModel::table;
  c.engine.outcomes.dry_table = t;
  const AcousticObservations o = run_case(c, 2);
  const auto ts = writers::acoustic_tables(o);
  const io::Table& tb = table(ts, "outcomes_by_pair.csv");
  const auto& n = column(tb, "pair_collisions").ints;
  const auto& broke = column(tb, "broke").ints;
  const int dry = static_cast<int>(PairType::dry);
  std::printf("dry collisions %lld, broke %lld\n", static_cast<long long>(n[dry]), static_cast<long long>(broke[dry]));
  ASSERT_GT(n[dry], 20) << "dry pairs: a case without them would test little";
  EXPECT_EQ(broke[dry], static_cast<std::int64_t>(o.stats.breakups[dry]));
  EXPECT_GT(broke[dry], 0);
  EXPECT_EQ(broke[0] + broke[2], 0) << "only dry pairs break";
  EXPECT_EQ(n[dry], column(tb, "stuck").ints[dry] + column(tb, "bounced").ints[dry] + broke[dry]);
  EXPECT_NE(o.log.find(fmt::format("dry: {}: ", n[dry])), std::string::npos) << o.log;
  EXPECT_NE(o.log.find(fmt::format(" / {} (", broke[dry])), std::string::npos) << o.log;
  // The same outcomes and PSD on one thread (each cell draws from its own counter-based stream).
  const AcousticObservations o1 = run_case(c, 1);
  const auto ts1 = writers::acoustic_tables(o1);
  EXPECT_EQ(csv_of(table(ts1, "outcomes_by_pair.csv")), csv_of(tb));
  EXPECT_EQ(csv_of(table(ts1, "efficiency.csv")), csv_of(table(ts, "efficiency.csv")));
  // And after a restart from the checkpoint of step 30.
  std::string payload;
  run_case(c, 2, nullptr, &payload);
  ASSERT_FALSE(payload.empty());
  const auto tr = writers::acoustic_tables(run_case(c, 1, &payload));
  EXPECT_EQ(csv_of(table(tr, "outcomes_by_pair.csv")), csv_of(tb));
  EXPECT_EQ(csv_of(table(tr, "efficiency.csv")), csv_of(table(ts, "efficiency.csv")));
}

TEST(OutcomesByPair, SameAfterARestartAndAtAnyThreadCount) {
  const AcousticCase c = test::parse_case(pair_case());
  const auto files = [](const AcousticObservations& o) {
    const auto ts = writers::acoustic_tables(o);
    return csv_of(table(ts, "outcomes_by_pair.csv")) + csv_of(table(ts, "efficiency.csv"));
  };
  const std::string one = files(run_case(c, 1));
  EXPECT_EQ(files(run_case(c, 2)), one);
  std::string payload;
  run_case(c, 2, nullptr, &payload);
  ASSERT_FALSE(payload.empty());
  EXPECT_EQ(files(run_case(c, 1, &payload)), one);
  // Negative control: another seed gives other counts.
  const AcousticCase other = test::parse_case(pair_case(6));
  EXPECT_NE(files(run_case(other, 2)), one);
}

TEST(OutcomesByPair, SectionalRunsHaveNeitherTheTableNorPmColumns) {
  AcousticObservations o;
  o.efficiency.resize(1);
  const auto ts = writers::acoustic_tables(o);
  for (const auto& t : ts) EXPECT_NE(t.file(), "outcomes_by_pair.csv");
  for (const auto& col : table(ts, "efficiency.csv").columns()) EXPECT_EQ(col.name.find("pm"), std::string::npos);
}

}  // namespace
}  // namespace agglo::acoustics
