// The DSMC step's thread count on a shared machine (thread_choice.hpp): the probes choose the faster
// count, the stretch between probes grows while the choice holds and restarts when it changes
// (synthetic step times; the engine's bits while the count switches: test_engine.cpp).
#include <cstdlib>

#include <gtest/gtest.h>

#include "agglo/acoustics/thread_choice.hpp"

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
