// Seed ensembles (run/seed_ensemble.hpp): the member seed rule, the exact JSON form of a dataset that
// carries each member's results, mean and standard error against their formula and against separate
// single runs of the members' seeds, member 0 = the single run, and results independent of the
// thread count.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

#include "agglo/core/error.hpp"
#include "agglo/io/dataset_json.hpp"
#include "agglo/io/ensemble_stats.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/run/ensemble_request.hpp"
#include "agglo/run/seed_ensemble.hpp"

using namespace agglo;
using namespace agglo::run;

namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

std::filesystem::path temp_dir(const std::string& name) {
  auto p = std::filesystem::temp_directory_path() / ("agglo_test_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(p);
  return p;
}

// The seed-002 baseline cut to 10 ms and ~1000 samples: a fast case whose members still differ.
Config short_case() {
  Config cfg = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/seed002_baseline.toml");
  for (const char* s : {"time.end=0.01", "output.psd_times=[0.0,0.01]", "output.snapshot_times=[0.0]",
                        "output.plots=false", "population.0.samples=1000", "population.1.samples=40"})
    cfg.apply_override(s);
  return cfg;
}

RunContext quiet_context(int threads) {
  RunContext ctx;
  ctx.threads = threads;
  ctx.formats = {true, false};
  return ctx;
}

// Every variable of `a` equals `b`'s bit for bit (reals and ints), wall-clock timing aside.
void expect_same_data(const io::Dataset& a, const io::Dataset& b) {
  ASSERT_EQ(a.variables.size(), b.variables.size());
  for (const auto& v : a.variables) {
    if (v.name.rfind("wall_time_s", 0) == 0) continue;
    const io::Variable* w = b.find(v.name);
    ASSERT_NE(w, nullptr) << v.name;
    EXPECT_EQ(v.dims, w->dims) << v.name;
    EXPECT_EQ(v.ints, w->ints) << v.name;
    ASSERT_EQ(v.reals.size(), w->reals.size()) << v.name;
    for (std::size_t i = 0; i < v.reals.size(); ++i) EXPECT_EQ(bits(v.reals[i]), bits(w->reals[i])) << v.name << "[" << i << "]";
  }
}

}  // namespace

TEST(SeedEnsemble, MemberSeedsFollowTheDocumentedRule) {
  const std::int64_t base = 20230064702;
  const auto s = member_seeds(base, 10);
  ASSERT_EQ(s.size(), 10u);
  EXPECT_EQ(s[0], base);  // member 0 is the single run
  // s_k = splitmix64(splitmix64(b) + k) & (2^63 - 1), computed here from the published constants.
  auto mix = [](std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  };
  for (std::size_t k = 1; k < s.size(); ++k) {
    EXPECT_EQ(static_cast<std::uint64_t>(s[k]), mix(mix(static_cast<std::uint64_t>(base)) + k) & 0x7fffffffffffffffull);
    EXPECT_GE(s[k], 0);
    for (std::size_t j = 0; j < k; ++j) EXPECT_NE(s[k], s[j]);
  }
  // A member's seed depends on (base, index) only: a larger ensemble extends a smaller one.
  const auto more = member_seeds(base, 25);
  EXPECT_TRUE(std::equal(s.begin(), s.end(), more.begin()));
  EXPECT_EQ(member_seeds(base, 1), std::vector<std::int64_t>{base});
  EXPECT_NE(member_seeds(base + 1, 2)[1], s[1]);
}

TEST(SeedEnsemble, PlanRejectsMemberCountsBelowOneAndCommandsWithoutSeed) {
  const auto& acoustic = find_command("acoustic");
  const auto dir = temp_dir("plan_refusals");
  for (long long n : {0LL, -3LL}) {
    try {
      (void)plan_ensemble({"acoustic", short_case(), {}, n, dir}, quiet_context(1));
      ADD_FAILURE() << "n = " << n << " accepted";
    } catch (const ConfigError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("--seeds " + std::to_string(n)), std::string::npos) << m;
      EXPECT_NE(m.find(">= 1"), std::string::npos) << m;
    }
  }
  EXPECT_THROW((void)plan_ensemble({"electrostatics", short_case(), {}, 2, dir}, quiet_context(1)), ConfigError);
  RunContext checkpointing = quiet_context(1);
  checkpointing.checkpoint_interval = 0.005;
  try {
    (void)plan_ensemble({"acoustic", short_case(), {}, 2, dir}, checkpointing);
    ADD_FAILURE() << "--checkpoint accepted with --seeds";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("--checkpoint 0.005 with --seeds 2"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir));  // refused before anything is made
  const auto plan = plan_ensemble({"acoustic", short_case(), {}, 3, dir}, quiet_context(1));
  EXPECT_TRUE(plan.sweep.keep_data);
  ASSERT_EQ(plan.sweep.cases.size(), 3u);
  EXPECT_EQ(plan.sweep.cases[0].assignments[0], "seed=20230064702");
  EXPECT_EQ(plan.recorded, "acoustic");  // run.json names the command, not "sweep"
  EXPECT_EQ(plan.details.value("ensemble", ""), "seeds");
  EXPECT_EQ(plan.details.value("members", 0), 3);
  EXPECT_FALSE(plan.details.contains("param"));
  const auto sweep = plan_sweep(acoustic, short_case(), {{"seed", {"20230064702"}}});
  EXPECT_FALSE(sweep.keep_data);
  EXPECT_NE(sweep.journal_key, plan.sweep.journal_key);  // a plain sweep's journal is never taken for an ensemble
}

TEST(SeedEnsemble, DatasetJsonRoundTripIsBitwiseExact) {
  io::Dataset d;
  d.add_dim("time", 4);
  d.add_dim("x", 3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> reals = {0.1, -0.0, 5e-324, std::numeric_limits<double>::max(), 1.0 / 3.0, -nan,
                                     std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                     std::bit_cast<double>(0x7ff4000000000123ull), 2.5e-308, 6.02214076e23, nan};
  d.add("field", {"time", "x"}, "m s-1", "a field", reals).attributes = {{"note", "x"}, {"flag_values", {0, 1}}};
  d.add_ints("count", {"x"}, "1", "counts", {std::numeric_limits<std::int64_t>::min(), 0,
                                             std::numeric_limits<std::int64_t>::max()});
  d.add("scalar", {}, "J", "a scalar", {nan});
  d.attributes = {{"title", "t"}, {"n", 3}};
  const auto text = io::dataset_to_json(d).dump();  // as the journal stores it
  const io::Dataset back = io::dataset_from_json(nlohmann::json::parse(text));
  EXPECT_EQ(back.dims, d.dims);
  EXPECT_EQ(back.attributes, d.attributes);
  ASSERT_EQ(back.variables.size(), d.variables.size());
  for (std::size_t k = 0; k < d.variables.size(); ++k) {
    const auto &a = d.variables[k], &b = back.variables[k];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.dims, b.dims);
    EXPECT_EQ(a.units, b.units);
    EXPECT_EQ(a.long_name, b.long_name);
    EXPECT_EQ(a.integer, b.integer);
    EXPECT_EQ(a.ints, b.ints);
    EXPECT_EQ(a.attributes, b.attributes);
    ASSERT_EQ(a.reals.size(), b.reals.size());
    for (std::size_t i = 0; i < a.reals.size(); ++i) EXPECT_EQ(bits(a.reals[i]), bits(b.reals[i])) << a.name << i;
  }
  EXPECT_THROW(io::dataset_from_json(nlohmann::json::parse(R"({"dims": [], "variables": [{"name": "v"}]})")),
               std::invalid_argument);
}

TEST(SeedEnsemble, MeanAndStandardErrorFollowTheirFormula) {
  const auto s = io::mean_stderr({1.0, 2.0, 3.0, 4.0});  // var = 5/3 (n - 1), stderr = sqrt(var / 4)
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.standard_error, std::sqrt(5.0 / 12.0));
  EXPECT_EQ(s.n, 4u);
  EXPECT_TRUE(std::isnan(io::mean_stderr({7.0}).standard_error));
  EXPECT_EQ(io::mean_stderr({7.0}).mean, 7.0);
  // Summary scalars: nested names flattened, missing or non-finite values left out of n.
  const auto stats = io::summary_stats({{{"a_s", 1.0}, {"b", {{"c", 2}}}},
                                        {{"a_s", 3.0}, {"b", {{"c", std::numeric_limits<double>::quiet_NaN()}}}},
                                        {{"a_s", 5.0}}});
  ASSERT_EQ(stats.size(), 2u);
  EXPECT_EQ(stats[0].quantity, "a_s");
  EXPECT_EQ(stats[0].unit, "s");
  EXPECT_DOUBLE_EQ(stats[0].value.mean, 3.0);
  EXPECT_DOUBLE_EQ(stats[0].value.standard_error, std::sqrt(4.0 / 3.0));
  EXPECT_EQ(stats[1].quantity, "b.c");
  EXPECT_EQ(stats[1].value.n, 1u);
}

TEST(SeedEnsemble, VariablesOnCoordinatesThatDifferAreNotAveraged) {
  auto member = [](double t1, double v) {
    io::Dataset d;
    d.add_dim("time", 2);
    d.add("time", {"time"}, "s", "time", {0.0, t1});
    d.add("y", {"time"}, "1", "y", {v, 2 * v});
    d.add("s", {}, "1", "s", {v});
    return d;
  };
  const auto same = io::ensemble_dataset({member(1.0, 1.0), member(1.0, 3.0)});
  ASSERT_NE(same.find("y_mean"), nullptr);
  EXPECT_EQ(same.find("y_mean")->reals, (std::vector<double>{2.0, 4.0}));
  EXPECT_EQ(same.find("y_stderr")->reals, (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(same.find("time")->reals, (std::vector<double>{0.0, 1.0}));
  const auto differ = io::ensemble_dataset({member(1.0, 1.0), member(2.0, 3.0)});
  EXPECT_EQ(differ.find("y_mean"), nullptr);
  EXPECT_NE(differ.find("s_mean"), nullptr);
  EXPECT_EQ(differ.attributes.value("not_averaged", ""), "time y");
}

TEST(SeedEnsemble, StatisticsEqualThoseOfSeparateSingleRunsAndDoNotDependOnThreads) {
  const auto& cmd = find_command("acoustic");
  const Config base = short_case();
  const auto dir = temp_dir("seed_ensemble");
  const auto ens = execute_ensemble({"acoustic", base.clone(), {}, 3, dir / "two"}, quiet_context(2));
  const auto ens1 = execute_ensemble({"acoustic", base.clone(), {}, 3, dir / "one"}, quiet_context(1));
  ASSERT_TRUE(ens.data && ens1.data);
  expect_same_data(*ens.data, *ens1.data);  // whatever the thread count
  const auto seeds = ens.data->attributes.at("seeds").get<std::vector<std::int64_t>>();
  EXPECT_EQ(seeds, member_seeds(cmd.seed(base), 3));
  ASSERT_EQ(ens.points.size(), 1u);
  EXPECT_EQ(ens.point_folders, std::vector<std::string>{""});  // no axes: the statistics in the folder itself

  // The members' own single runs, made here with each member's seed in folders of their own.
  std::vector<io::DatasetPtr> singles;
  nlohmann::json summary0;
  for (std::size_t k = 0; k < 3; ++k) {
    Config cfg = base.clone();
    if (k > 0) cfg.apply_override("seed=" + std::to_string(seeds[k]));  // member 0: the case as it is
    auto r = execute(cmd, cfg, dir / ("single_" + std::to_string(k)), quiet_context(2));
    if (k == 0) summary0 = r.summary;
    singles.push_back(r.data);
  }
  // Member 0 is the plain single run of the case.
  EXPECT_EQ(ens.runs.cases[0].folder, "case_00_20230064702");
  for (const char* q : {"fine_efficiency", "n_solid_final_cm3"})
    EXPECT_EQ(ens.runs.summaries[0].at(q).get<double>(), summary0.at(q).get<double>()) << q;

  for (const char* name : {"fine_efficiency", "n_solid_cm3", "pure_droplet_fraction", "collisions"}) {
    const auto* mean = ens.data->find(std::string(name) + "_mean");
    const auto* error = ens.data->find(std::string(name) + "_stderr");
    ASSERT_TRUE(mean && error) << name;
    for (std::size_t i = 0; i < mean->size(); ++i) {
      double x[3];
      for (std::size_t k = 0; k < 3; ++k) {
        const auto* v = singles[k]->find(name);
        x[k] = v->integer ? static_cast<double>(v->ints[i]) : v->reals[i];
      }
      const double m = (x[0] + x[1] + x[2]) / 3.0;
      const double se = std::sqrt(((x[0] - m) * (x[0] - m) + (x[1] - m) * (x[1] - m) + (x[2] - m) * (x[2] - m)) / 6.0);
      EXPECT_DOUBLE_EQ(mean->reals[i], m) << name << "[" << i << "]";
      EXPECT_NEAR(error->reals[i], se, 1e-12 * std::abs(m)) << name << "[" << i << "]";
    }
  }
  // The members differ (their seeds are used): the final efficiency has a standard error.
  const auto* eff = ens.data->find("fine_efficiency_stderr");
  EXPECT_GT(eff->reals.back(), 0.0);
  std::filesystem::remove_all(dir);
}

namespace {

std::string text_of(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// ensemble_summary.csv without its wall-time row.
std::string untimed(const std::filesystem::path& p) {
  std::istringstream in(text_of(p));
  std::string line, out;
  while (std::getline(in, line))
    if (line.rfind("wall_time_s,", 0) != 0) out += line + "\n";
  return out;
}

}  // namespace

// The one request of every ensemble (run/ensemble_request.hpp): a case is parsed once per run, a seeded
// sweep gives every point the whole statistics of `acoustic --seeds` at that point (time series and size
// distributions, not only the summary scalars), and run.json's details are made once for every front end.

TEST(EnsembleRequest, EveryCaseIsParsedOncePerRun) {
  const auto dir = temp_dir("parse_once");
  // 2 points x 2 seeds = 4 runs; the ensemble's own config.resolved.toml parses the base once more.
  std::size_t before = case_parses();
  auto plan = plan_ensemble({"acoustic", short_case(), {{"population.1.diameter", {"20e-6", "40e-6"}}}, 2, dir / "s"},
                            quiet_context(2));
  (void)execute_ensemble(plan, quiet_context(2));
  EXPECT_EQ(case_parses() - before, 4u + 1u);
  // A seed ensemble without axes: its member 0 is the base case, so exactly one parse per member.
  before = case_parses();
  (void)execute_ensemble({"acoustic", short_case(), {}, 3, dir / "e"}, quiet_context(2));
  EXPECT_EQ(case_parses() - before, 3u);
  // A single run: once.
  before = case_parses();
  Config one = short_case();
  (void)execute(find_command("acoustic"), one, dir / "one", quiet_context(2));
  EXPECT_EQ(case_parses() - before, 1u);
  std::filesystem::remove_all(dir);
}

TEST(EnsembleRequest, SweepPointsGetTheWholeStatisticsOfTheSeedEnsembleAtThatPoint) {
  const auto dir = temp_dir("points");
  const auto res = execute_ensemble(
      {"acoustic", short_case(), {{"population.1.diameter", {"20e-6", "40e-6"}}}, 3, dir / "s"}, quiet_context(2));
  ASSERT_EQ(res.point_folders, (std::vector<std::string>{"point_00_20e-6", "point_01_40e-6"}));
  Config at = short_case();
  at.apply_override("population.1.diameter=40e-6");
  const auto ens = execute_ensemble({"acoustic", std::move(at), {}, 3, dir / "e"}, quiet_context(2));
  const auto point = dir / "s" / "point_01_40e-6";
  // The time series of the point's mean and s.e. are those of `acoustic --seeds 3` at 40e-6, byte for byte.
  const auto series = text_of(point / "ensemble_timeseries.csv");
  EXPECT_NE(series.find("fine_efficiency_mean,fine_efficiency_stderr"), std::string::npos);
  EXPECT_EQ(series, text_of(dir / "e" / "ensemble_timeseries.csv"));
  EXPECT_EQ(untimed(point / "ensemble_summary.csv"), untimed(dir / "e" / "ensemble_summary.csv"));
  // ... and differ from the other point's.
  EXPECT_NE(series, text_of(dir / "s" / "point_00_20e-6" / "ensemble_timeseries.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "s" / "sweep_ensemble.csv"));
  // run.json: the sweep as "sweep" with its axes, the seed ensemble as its command.
  EXPECT_NE(text_of(dir / "s" / "run.json").find("\"command\": \"sweep\""), std::string::npos);
  const auto run_json = text_of(dir / "e" / "run.json");
  EXPECT_NE(run_json.find("\"command\": \"acoustic\""), std::string::npos) << run_json;
  EXPECT_EQ(run_json.find("\"command\": \"sweep\""), std::string::npos) << run_json;
  std::filesystem::remove_all(dir);
}

TEST(EnsembleRequest, DetailsNameTheAxesAndTheMembers) {
  const auto one = ensemble_details("collide", {{"projectile.speed", {"0.1", "0.2"}}}, {});
  EXPECT_EQ(one, (nlohmann::json{{"command", "collide"}, {"param", "projectile.speed"}, {"values", {"0.1", "0.2"}}}));
  const auto grid = ensemble_details("acoustic", {{"a", {"1", "2"}}, {"b", {"x"}}}, {7, 9});
  EXPECT_EQ(grid.at("param"), (nlohmann::json{"a", "b"}));
  EXPECT_EQ(grid.at("values"), (nlohmann::json{"1,2", "x"}));
  EXPECT_EQ(grid.at("members"), 2);
  EXPECT_EQ(grid.at("seeds"), (nlohmann::json{7, 9}));
  const auto seeds = ensemble_details("acoustic", {}, {7, 9, 11});
  EXPECT_FALSE(seeds.contains("param"));
  EXPECT_EQ(seeds.at("ensemble"), "seeds");
}

TEST(EnsembleRequest, FormatsAreParsedByOneFunction) {
  EXPECT_TRUE(parse_formats("csv").csv);
  EXPECT_FALSE(parse_formats("csv").netcdf);
  const auto both = parse_formats("netcdf,csv");
  EXPECT_TRUE(both.csv && both.netcdf);
  for (const char* bad : {"", "xml", "csv,", "csv,,netcdf"}) EXPECT_THROW((void)parse_formats(bad), ConfigError) << bad;
}
