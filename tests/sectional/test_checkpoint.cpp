// Exact restart of sectional runs (sectional/checkpoint.hpp, docs/restart.md): a run resumed from any of
// its checkpoints gives the uninterrupted run's observations and final state bit for bit.
#include <gtest/gtest.h>

#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "agglo/acoustics/checkpoint.hpp"
#include "agglo/core/error.hpp"
#include "agglo/sectional/checkpoint.hpp"
#include "agglo/sectional/run.hpp"
#include "helpers.hpp"

namespace agglo::sectional {
namespace {

struct Outcome {
  acoustics::AcousticObservations obs;
  std::vector<double> times;  // of the checkpoints written
  std::vector<std::string> payloads;
};

Outcome run(const SectionalCase& c, double interval, const std::string* resume = nullptr,
            std::function<bool()> cancelled = {}) {
  Outcome o;
  acoustics::RunHooks h;
  h.checkpoint_interval = interval;
  h.checkpoint = [&](std::uint64_t, double t, const std::string& payload) {
    o.times.push_back(t);
    o.payloads.push_back(payload);
  };
  h.cancelled = std::move(cancelled);
  std::optional<io::CheckpointReader> reader;
  if (resume) reader.emplace(*resume, "test checkpoint");
  h.resume = reader ? &*reader : nullptr;
  o.obs = run_sectional(c, h);
  return o;
}

// Everything a run reports, as bytes (run.log without its wall time).
std::string observed(acoustics::AcousticObservations o) {
  o.log = std::regex_replace(o.log, std::regex("wall_time=[0-9.]+ s"), "wall_time=X");
  io::CheckpointWriter w;
  acoustics::save_observations(o, w);
  w.pod(o.final);
  w.u64(o.steps);
  w.u64(o.samples);
  return w.bytes();
}

// The Brownian benchmark case shortened to 2 h: output times every 60 s and at the PSD times.
SectionalCase brownian() {
  return test::shipped_case("partmc_brownian", {"time.end=7200.0", "output.psd_times=[0.0,3600.0,7200.0]"});
}

TEST(SectionalCheckpoint, ResumeFromEveryCheckpointEqualsTheUninterruptedRun) {
  const SectionalCase c = brownian();
  const Outcome full = run(c, 1e9);
  ASSERT_EQ(full.times, std::vector<double>{7200.0});  // the end only
  ASSERT_GT(full.obs.steps, 20u);
  const Outcome every = run(c, 900.0);  // 900, 1800, ..., 7200 s: 8 checkpoints
  ASSERT_EQ(every.times.size(), 8u);
  EXPECT_TRUE(every.payloads.back() == full.payloads.back()) << "writing checkpoints changed the run";
  EXPECT_TRUE(observed(every.obs) == observed(full.obs));
  for (std::size_t i = 0; i < every.times.size(); ++i) {
    const Outcome resumed = run(c, 1e9, &every.payloads[i]);
    // Resumed from the end: the checkpoint in place is already the final state, none is written.
    ASSERT_EQ(resumed.payloads.size(), i + 1 < every.times.size() ? 1u : 0u);
    const std::string& last = resumed.payloads.empty() ? every.payloads[i] : resumed.payloads.back();
    EXPECT_TRUE(last == full.payloads.back()) << "final state, resumed at t = " << every.times[i];
    EXPECT_TRUE(observed(resumed.obs) == observed(full.obs)) << "observations, resumed at t = " << every.times[i];
  }
}

TEST(SectionalCheckpoint, CancelledRunWritesItsStateAndResumesExactly) {
  const SectionalCase c = brownian();
  const Outcome full = run(c, 1e9);
  // Cancelled at the 30th output time: the checkpoint of that state is written before the throw.
  std::string payload;
  acoustics::RunHooks h;
  h.checkpoint_interval = 1e9;
  h.checkpoint = [&](std::uint64_t, double, const std::string& p) { payload = p; };
  int checks = 0;
  h.cancelled = [&] { return ++checks == 30; };
  EXPECT_THROW(run_sectional(c, h), InterruptedError);
  ASSERT_FALSE(payload.empty());
  const Outcome resumed = run(c, 1e9, &payload);
  EXPECT_TRUE(resumed.payloads.back() == full.payloads.back());
  EXPECT_TRUE(observed(resumed.obs) == observed(full.obs));
}

TEST(SectionalCheckpoint, PayloadOfAnotherGridIsRefused) {
  const Outcome o = run(brownian(), 1e9);
  SectionalSolver other(test::shipped_case("partmc_brownian", {"sectional.bins_per_decade=20"}));
  io::CheckpointReader r(o.payloads.back(), "other.bin");
  EXPECT_THROW(load_solver(other, r), ConfigError);
}

}  // namespace
}  // namespace agglo::sectional
