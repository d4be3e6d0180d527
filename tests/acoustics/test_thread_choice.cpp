// The DSMC step's thread count on a shared machine (thread_choice.hpp): the probes choose the faster
// count, the stretch between probes doubles while the choice holds and restarts when it changes; and
// an engine large enough to run its steps in parallel gives every bit of the one-thread run while the
// choice switches between two threads and one. (Steps "taking" 0.6 or 1.5 of a unit: synthetic times.)
#include <cstdlib>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include "agglo/acoustics/engine.hpp"
#include "helpers.hpp"

using namespace agglo::acoustics;

namespace {

// Steps a chooser through n steps, each taking many_s at its max count and one_s at one thread;
// returns how many of them ran at the max count.
std::uint64_t drive(ThreadChoice& tc, int max_threads, std::uint64_t n, double many_s, double one_s) {
  std::uint64_t at_max = 0;
  for (std::uint64_t s = 0; s < n; ++s) {
    const int t = tc.next(max_threads);
    EXPECT_TRUE(t == 1 || t == max_threads);
    at_max += t == max_threads ? 1 : 0;
    tc.record(t == max_threads ? many_s : one_s);
  }
  return at_max;
}

}  // namespace

TEST(ThreadChoice, ProbesThenRunsTheFasterCountWithGrowingStretches) {
  constexpr std::uint64_t P = ThreadChoice::kProbeSteps, S = ThreadChoice::kFirstStretch;
  ThreadChoice fast;  // two threads take 0.6 of one thread's time
  EXPECT_EQ(drive(fast, 2, P, 0.6, 1.0), P);  // first probe at two threads
  EXPECT_EQ(drive(fast, 2, P, 0.6, 1.0), 0u);  // then one thread
  EXPECT_EQ(drive(fast, 2, S, 0.6, 1.0), S);   // the faster count for the first stretch
  EXPECT_EQ(drive(fast, 2, 2 * P, 0.6, 1.0), P);
  EXPECT_EQ(drive(fast, 2, 4 * S, 0.6, 1.0), 4 * S);  // same choice: the stretch grew 4x
  EXPECT_EQ(drive(fast, 2, P, 0.6, 1.0), P);
  EXPECT_EQ(fast.steps_at_one(), 2 * P);

  ThreadChoice slow;  // two threads take 1.5 times one thread's time (a busy machine)
  drive(slow, 2, 2 * P, 1.5, 1.0);
  EXPECT_EQ(drive(slow, 2, S, 1.5, 1.0), 0u);
  // the machine frees up: the next probe switches to two threads, for the first stretch again
  drive(slow, 2, 2 * P, 0.6, 1.0);
  EXPECT_EQ(drive(slow, 2, S, 0.6, 1.0), S);
  EXPECT_EQ(drive(slow, 2, P, 0.6, 1.0), P);  // probing again after S steps
}

TEST(ThreadChoice, OneThreadOrFixedMeasuresNothing) {
  ThreadChoice one;
  EXPECT_EQ(one.next(1), 1);
  EXPECT_FALSE(one.measuring());
  ThreadChoice restarted;
  drive(restarted, 2, ThreadChoice::kProbeSteps + 1, 1.5, 1.0);
  EXPECT_EQ(restarted.next(3), 3);  // a new max count restarts the probes at that count
  EXPECT_TRUE(restarted.measuring());
  setenv("AGGLO_THREAD_PROBE", "off", 1);
  ThreadChoice fixed;
  EXPECT_EQ(drive(fixed, 2, 3 * ThreadChoice::kProbeSteps, 1.5, 1.0), 3 * ThreadChoice::kProbeSteps);
  EXPECT_FALSE(fixed.measuring());
  unsetenv("AGGLO_THREAD_PROBE");
}

TEST(ThreadChoice, EngineBitwiseTheSameWhileTheCountSwitches) {
  // 4200 fine samples: above the engine's parallel threshold (4096), so two threads run the steps in
  // parallel; 100 steps cover a probe at two threads, one at one thread and the start of a stretch.
  const std::string toml = R"(
seed = 7
[sound]
level_db = 145.0
frequency_hz = 2000.0
[time]
end = 0.001
collision_dt = 1e-5
[[population]]
name = "fines"
phase = "solid"
distribution = "lognormal"
geometric_mean_diameter = 0.5e-6
geometric_std = 2.0
bins = 20
number_concentration = 5e11
samples = 4200
[[population]]
name = "droplets"
phase = "liquid"
distribution = "monodisperse"
diameter = 30e-6
number_concentration = 5e9
samples = 100
)";
  auto run = [&](int threads) {
    omp_set_num_threads(threads);
    Engine e = test::make_engine(toml);
    for (int s = 0; s < 100; ++s) e.step();
    return e;
  };
  const int saved = omp_get_max_threads();
  const Engine a = run(1);
  const Engine b = run(2);
  omp_set_num_threads(saved);
  EXPECT_GE(a.particles().size(), 4096u);
  // (after the probes the count depends on this machine's timing: steps 65-100 at two threads or one)
  EXPECT_EQ(b.thread_choice().steps_at_max() + b.thread_choice().steps_at_one(), 100u);
  EXPECT_GE(b.thread_choice().steps_at_max(), ThreadChoice::kProbeSteps);
  EXPECT_GE(b.thread_choice().steps_at_one(), ThreadChoice::kProbeSteps);
  ASSERT_GT(a.stats().collisions, 0u);
  EXPECT_EQ(a.stats().collisions, b.stats().collisions);
  const SampleSet &p = a.particles(), &q = b.particles();
  ASSERT_EQ(p.size(), q.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_EQ(p.x[i], q.x[i]) << i;
    ASSERT_EQ(p.vx[i], q.vx[i]) << i;
    ASSERT_EQ(p.vz[i], q.vz[i]) << i;
    ASSERT_EQ(p.w[i], q.w[i]) << i;
    ASSERT_EQ(p.vol_s[i], q.vol_s[i]) << i;
  }
}
