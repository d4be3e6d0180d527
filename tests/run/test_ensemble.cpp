// The ensemble runner, its journal and the sweep grid (src/agglo/run): results keyed by job index
// whatever the thread count, failures kept per job while the others complete, cancellation, the
// journal's resume semantics, and v_crit independent of the number of threads.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>
#include <unistd.h>

#include "agglo/core/error.hpp"
#include "agglo/impact/vcrit.hpp"
#include "agglo/io/sweep_table.hpp"
#include "agglo/run/ensemble.hpp"
#include "agglo/run/sweep.hpp"

using namespace agglo;
using namespace agglo::run;

namespace {

std::vector<Job> square_jobs(std::size_t n, std::atomic<int>* calls = nullptr) {
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < n; ++i)
    jobs.push_back({"job " + std::to_string(i), [i, calls](const JobContext& ctx) {
                      if (calls) ++*calls;
                      EXPECT_EQ(ctx.index, i);
                      return nlohmann::json(static_cast<double>(i * i));
                    }});
  return jobs;
}

std::filesystem::path temp_file(const std::string& name) {
  auto p = std::filesystem::temp_directory_path() / ("agglo_test_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove(p);
  return p;
}

}  // namespace

TEST(Ensemble, ResultsByIndexAtAnyThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    const auto out = run_jobs(square_jobs(17), {threads});
    ASSERT_EQ(out.size(), 17u);
    for (std::size_t i = 0; i < out.size(); ++i) {
      EXPECT_FALSE(out[i].error);
      EXPECT_EQ(out[i].result.get<double>(), static_cast<double>(i * i)) << "threads " << threads;
    }
  }
}

TEST(Ensemble, FailuresAreKeptPerJobAndOthersComplete) {
  auto jobs = square_jobs(6);
  jobs[2].run = [](const JobContext&) -> nlohmann::json { throw NumericalError("job 2 blew up"); };
  jobs[4].run = [](const JobContext&) -> nlohmann::json { throw ConfigError("job 4 bad"); };
  const auto out = run_jobs(jobs, {2});
  EXPECT_TRUE(out[2].error);
  EXPECT_TRUE(out[4].error);
  for (std::size_t i : {0u, 1u, 3u, 5u}) EXPECT_EQ(out[i].result.get<double>(), static_cast<double>(i * i));
  EXPECT_THROW(rethrow_first_error(out), NumericalError);  // the first failure in index order
}

TEST(Ensemble, CancelledTokenStartsNoJob) {
  std::atomic<int> calls{0};
  CancelToken token;
  token.cancel();
  const auto out = run_jobs(square_jobs(5, &calls), {2, nullptr, &token});
  EXPECT_EQ(calls.load(), 0);
  EXPECT_THROW(rethrow_first_error(out), InterruptedError);
}

TEST(Journal, ResumeRepeatsOnlyMissingJobs) {
  const auto file = temp_file("journal.jsonl");
  std::atomic<int> calls{0};
  {
    Journal j(file, "ctx-A", false);
    auto jobs = square_jobs(4, &calls);
    jobs.resize(2);  // an interrupted first run: 2 of 4 jobs finished
    run_jobs(jobs, {2, &j});
  }
  EXPECT_EQ(calls.load(), 2);
  {
    std::ofstream(file, std::ios::app) << "{\"context\": \"ctx-A\", \"job\": \"torn";  // killed mid-line
  }
  calls = 0;
  Journal resumed(file, "ctx-A", true);
  EXPECT_EQ(resumed.loaded(), 2u);
  const auto out = run_jobs(square_jobs(4, &calls), {2, &resumed});
  EXPECT_EQ(calls.load(), 2);  // only jobs 2 and 3 ran
  EXPECT_TRUE(out[0].reused && out[1].reused && !out[2].reused);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(out[i].result.get<double>(), static_cast<double>(i * i));
  Journal other(file, "ctx-B", true);  // another case: nothing reused
  EXPECT_EQ(other.loaded(), 0u);
  Journal fresh(file, "ctx-A", false);  // without --resume the journal starts anew
  EXPECT_EQ(fresh.loaded(), 0u);
  EXPECT_FALSE(std::filesystem::exists(file));
}

// A journal line that cannot be written fails its job with an OutputError naming the file (it was lost
// without a word, and --resume then repeated the job), and the ensemble's error keeps that type, so the
// run ends as a full disk does (exit 2, the folder marked failed).
TEST(Journal, AnAppendThatFailsFailsTheJob) {
  const auto file = temp_file("gone") / "journal.jsonl";  // its folder does not exist
  Journal j(file, "ctx", false);
  auto jobs = square_jobs(2);
  const auto out = run_jobs(jobs, {1, &j});
  ASSERT_TRUE(out[0].error && out[1].error);
  try {
    rethrow_first_error(out, &jobs);
    FAIL() << "no error thrown";
  } catch (const OutputError& e) {
    EXPECT_EQ(std::string(e.what()), "job 'job 0' (all 2 jobs failed): cannot write " + file.string() +
                                         ": No such file or directory (free space, or choose another --out)");
  }
  EXPECT_EQ(j.find("job 0"), std::nullopt);
}

TEST(Journal, ContextIgnoresOnlyTheNamedSections) {
  const std::string toml = "name = \"x\"\n[material]\ndensity = 2500\n[vcrit]\ntolerance = 0.001\n[vcrit.sub]\na = 1\n"
                           "[time]\ndt = 0\n";
  EXPECT_EQ(without_sections(toml, {"vcrit"}), "name = \"x\"\n[material]\ndensity = 2500\n[time]\ndt = 0\n");
  EXPECT_NE(hash_hex("a"), hash_hex("b"));
  EXPECT_EQ(hash_hex(""), "cbf29ce484222325");  // FNV-1a 64 offset basis
}

TEST(Sweep, GridIsCartesianLastAxisFastest) {
  const auto cases = sweep_grid({{"a.x", {"1", "2"}}, {"b.y", {"p", "q", "r"}}});
  ASSERT_EQ(cases.size(), 6u);
  EXPECT_EQ(cases[0].assignments, (std::vector<std::string>{"a.x=1", "b.y=p"}));
  EXPECT_EQ(cases[4].assignments, (std::vector<std::string>{"a.x=2", "b.y=q"}));
  EXPECT_EQ(cases[4].folder, "case_04_2_q");
  EXPECT_EQ(sweep_grid({{"k", {"10e-6"}}})[0].folder, "case_00_10e-6");
  EXPECT_THROW(sweep_grid({{" ", {"1"}}}), ConfigError);
  EXPECT_THROW(sweep_grid({}), ConfigError);
  EXPECT_THROW(split_values("1,,2"), ConfigError);
  EXPECT_THROW(split_values("10e-6,"), ConfigError);
  EXPECT_THROW(split_values(",10e-6"), ConfigError);
  EXPECT_THROW(split_values(""), ConfigError);
  EXPECT_THROW(sweep_grid({{"\t\n", {"1"}}}), ConfigError);
  EXPECT_EQ(split_values(" 1 ,\t2"), (std::vector<std::string>{"1", "2"}));
}

TEST(Sweep, CsvFieldsQuotedOnlyWhenNeeded) {
  EXPECT_EQ(io::csv_field("10e-6"), "10e-6");
  EXPECT_EQ(io::csv_field("case_00_a"), "case_00_a");
  EXPECT_EQ(io::csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(io::csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(io::csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(io::csv_field("cr\r"), "\"cr\r\"");
}

TEST(Vcrit, SpeedsTriedDoNotDependOnThreads) {
  // Non-monotonic synthetic outcome: breaks above 0.3, and in the window (0.2, 0.21). With a fixed
  // points_per_round, the speeds tried -- and so v_crit -- are the same on any number of threads.
  impact::VcritSpec spec;
  spec.v_min = 0.05;
  spec.v_max = 0.6;
  spec.scan_points = 5;
  spec.tolerance = 1e-3;
  spec.points_per_round = 2;
  auto batch_on = [](int threads) {
    return [threads](const std::vector<double>& speeds, const impact::StopRule&) {
      std::vector<Job> jobs;
      for (double v : speeds)
        jobs.push_back({"", [v](const JobContext&) {
                          return nlohmann::json{v, v > 0.3 || (v > 0.2 && v < 0.21)};
                        }});
      std::vector<impact::ImpactOutcome> out;
      for (const auto& o : run_jobs(jobs, {threads})) {
        impact::ImpactOutcome r;
        r.speed = o.result[0].get<double>();
        r.broken = o.result[1].get<bool>();
        r.contact = true;
        out.push_back(r);
      }
      return out;
    };
  };
  const auto a = impact::find_vcrit(spec, batch_on(1));
  const auto b = impact::find_vcrit(spec, batch_on(8));
  EXPECT_EQ(a.v_crit, b.v_crit);
  ASSERT_EQ(a.runs.size(), b.runs.size());
  for (std::size_t i = 0; i < a.runs.size(); ++i) EXPECT_EQ(a.runs[i].speed, b.runs[i].speed);
  EXPECT_GT(a.v_crit, 0.3);
  EXPECT_LE(a.v_crit - 0.3, spec.tolerance);
  EXPECT_EQ(a.rounds, b.rounds);
}

TEST(Ensemble, ErrorNamesTheFailedJobAndKeepsItsType) {
  auto jobs = square_jobs(4);
  jobs[1].run = [](const JobContext&) -> nlohmann::json { throw NumericalError("energy explosion"); };
  jobs[3].run = [](const JobContext&) -> nlohmann::json { throw NumericalError("NaN"); };
  const auto out = run_jobs(jobs, {2});
  try {
    rethrow_first_error(out, &jobs);
    FAIL() << "no error thrown";
  } catch (const NumericalError& e) {
    EXPECT_EQ(std::string(e.what()), "job 'job 1' (2 of 4 jobs failed; the others completed): energy explosion");
  }
  // Every job failed: no "others" that completed.
  for (auto& j : jobs) j.run = [](const JobContext&) -> nlohmann::json { throw NumericalError("NaN"); };
  try {
    rethrow_first_error(run_jobs(jobs, {2}), &jobs);
    FAIL() << "no error thrown";
  } catch (const NumericalError& e) {
    EXPECT_EQ(std::string(e.what()), "job 'job 0' (all 4 jobs failed): NaN");
  }
}

// EnsembleOptions::stop_after: jobs after the first whose result meets it are not needed. On one thread
// they never start; on several, the outcomes up to it are the same and a running later job sees
// JobContext::superseded() and stops (its outcome marked skipped, no error).
TEST(Ensemble, StopAfterSkipsTheJobsAfterTheFirstMatch) {
  std::atomic<int> calls{0};
  auto jobs = square_jobs(8, &calls);
  EnsembleOptions opt{1};
  opt.stop_after = [](const nlohmann::json& r) { return r.get<double>() == 9.0; };  // job 3
  const auto one = run_jobs(jobs, opt);
  EXPECT_EQ(calls.load(), 4);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(one[i].skipped, i > 3) << i;
    EXPECT_FALSE(one[i].error);
    if (i <= 3) {
      EXPECT_EQ(one[i].result.get<double>(), static_cast<double>(i * i));
    }
  }
  opt.threads = 4;
  const auto four = run_jobs(jobs, opt);
  for (std::size_t i = 0; i <= 3; ++i) EXPECT_EQ(four[i].result, one[i].result);
  // Negative control: without the rule every job runs.
  calls = 0;
  (void)run_jobs(jobs, EnsembleOptions{1});
  EXPECT_EQ(calls.load(), 8);
}

TEST(Ensemble, SupersededRunningJobStops) {
  std::atomic<bool> job1_started{false};
  std::vector<Job> jobs;
  jobs.push_back({"first", [&](const JobContext&) {
                    while (!job1_started) std::this_thread::yield();  // job 1 is running when this one ends
                    return nlohmann::json("stop");
                  }});
  jobs.push_back({"second", [&](const JobContext& ctx) {
                    job1_started = true;
                    for (long k = 0; k < 600'000'000L; ++k) {  // bounded: fails the test instead of hanging
                      if (ctx.superseded()) throw InterruptedError("superseded");
                      if (k % 1000 == 0) std::this_thread::yield();
                    }
                    return nlohmann::json("ran to the end");
                  }});
  EnsembleOptions opt{2};
  opt.stop_after = [](const nlohmann::json& r) { return r == "stop"; };
  const auto out = run_jobs(jobs, opt);
  EXPECT_EQ(out[0].result, "stop");
  EXPECT_TRUE(out[1].skipped);
  EXPECT_FALSE(out[1].error);
  EXPECT_TRUE(out[1].result.is_null());
}
