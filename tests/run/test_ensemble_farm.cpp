// What the MPI task farm (src/agglo/run/ensemble_farm.*) relies on, testable in one process: an outcome
// survives its message encoding exactly (results bit for bit incl. NaN and infinities; the error's type
// and message), jobs know they run inside an ensemble (a run_jobs inside a job stays in its process),
// and a journal torn by a killed run takes new entries on lines of their own. The farm itself runs
// under mpirun in tests/mpi/*.sh.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <unistd.h>

#include "agglo/core/error.hpp"
#include "agglo/run/ensemble.hpp"
#include "agglo/run/ensemble_farm.hpp"
#include "agglo/run/journal.hpp"

using namespace agglo;
using namespace agglo::run;

namespace {

// outcome -> JSON -> CBOR bytes (as the farm sends them) -> JSON -> outcome
JobOutcome through_message(const JobOutcome& o) {
  return outcome_from_json(nlohmann::json::from_cbor(nlohmann::json::to_cbor(outcome_to_json(o))));
}

template <class E>
void expect_error_kept(const char* message) {
  JobOutcome o;
  o.error = std::make_exception_ptr(E(message));
  const auto back = through_message(o);
  ASSERT_TRUE(back.error);
  try {
    std::rethrow_exception(back.error);
  } catch (const E& e) {
    EXPECT_STREQ(e.what(), message);
  } catch (...) {
    ADD_FAILURE() << "the error changed its type: " << message;
  }
}

}  // namespace

TEST(EnsembleFarm, ResultsSurviveTheMessageBitForBit) {
  JobOutcome o;
  const double values[] = {0.1 + 0.2, 1e-308, 5e-324, -0.0, std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN(), 1.0 / 3.0};
  for (double v : values) o.result["x"].push_back(v);
  o.result["n"] = -7;
  o.result["s"] = "v=0.20000000000000001";
  o.seconds = 0.25;
  const auto back = through_message(o);
  EXPECT_FALSE(back.error);
  ASSERT_EQ(back.result["x"].size(), std::size(values));
  for (std::size_t i = 0; i < std::size(values); ++i) {
    const double b = back.result["x"][i].get<double>();
    if (std::isnan(values[i])) {
      EXPECT_TRUE(std::isnan(b));
    } else {
      EXPECT_EQ(std::signbit(b), std::signbit(values[i]));
      EXPECT_EQ(b, values[i]);
    }
  }
  EXPECT_EQ(back.result["n"], -7);
  EXPECT_EQ(back.result["s"], "v=0.20000000000000001");
  EXPECT_EQ(back.seconds, 0.25);
}

TEST(EnsembleFarm, ErrorsKeepTheirTypeAndMessage) {
  expect_error_kept<InterruptedError>("interrupted");
  expect_error_kept<LimitError>("over the step budget");
  expect_error_kept<ConfigError>("bad key");
  expect_error_kept<NumericalError>("GMRES did not converge");
  expect_error_kept<std::runtime_error>("something else");
  // A LimitError is also a ConfigError (exit code 2) after the trip.
  JobOutcome o;
  o.error = std::make_exception_ptr(LimitError("budget"));
  EXPECT_THROW(std::rethrow_exception(through_message(o).error), ConfigError);
}

TEST(EnsembleFarm, JobsKnowTheyRunInsideAnEnsemble) {
  EXPECT_FALSE(in_job());
  std::vector<Job> jobs;
  for (int i = 0; i < 4; ++i)
    jobs.push_back({"job " + std::to_string(i), [](const JobContext&) {
                      // a nested ensemble inside a job: its own jobs are inside one too
                      std::vector<Job> inner{{"inner", [](const JobContext&) { return nlohmann::json(in_job()); }}};
                      const auto r = run_jobs(inner, {1});
                      return nlohmann::json::array({in_job(), r[0].result});
                    }});
  for (const auto& o : run_jobs(jobs, {2})) EXPECT_EQ(o.result, nlohmann::json::array({true, true}));
  EXPECT_FALSE(in_job());
}

TEST(EnsembleFarm, TornJournalLineIsEndedBeforeTheNextEntry) {
  const auto file = std::filesystem::temp_directory_path() / ("agglo_test_" + std::to_string(::getpid()) + "_torn.jsonl");
  {
    Journal j(file, "ctx", false);
    j.record("a", 0, 1.5, {{"rank", 1}, {"seconds", 0.1}});
  }
  std::ofstream(file, std::ios::app) << R"({"context":"ctx","job":"12)";  // a kill -9 in the middle of a line
  {
    Journal j(file, "ctx", true);
    EXPECT_EQ(j.loaded(), 1u);
    j.record("b", 1, 2.5);
  }
  Journal again(file, "ctx", true);
  EXPECT_EQ(again.loaded(), 2u);
  ASSERT_TRUE(again.find("b"));
  EXPECT_EQ(*again.find("b"), 2.5);
  std::filesystem::remove(file);
}
