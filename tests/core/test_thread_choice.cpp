// The step's thread count on a shared machine (core/thread_choice.hpp), on a synthetic machine: the count
// of every step of a long run, while two threads are first slower (a busy machine) and then faster than
// one; and AGGLO_THREAD_PROBE=off. (What the DEM does with it, bit for bit: test_dem_reference_twin.cpp.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "agglo/core/thread_choice.hpp"

using agglo::ThreadChoice;

namespace {

// Lengths of the runs of equal counts over `steps` steps, each taking `two` seconds on 2 threads up to step
// `change` and `two_after` after it, 1 s on one thread; counts[k] is the count of run k.
std::vector<std::uint64_t> runs_of(ThreadChoice& tc, std::uint64_t steps, double two, std::uint64_t change,
                                   double two_after, std::vector<int>& counts) {
  std::vector<std::uint64_t> len;
  for (std::uint64_t s = 0; s < steps; ++s) {
    const int t = tc.next(2);
    if (counts.empty() || counts.back() != t) {
      counts.push_back(t);
      len.push_back(0);
    }
    ++len.back();
    tc.record(t == 1 ? 1.0 : s < change ? two : two_after);
  }
  return len;
}

}  // namespace

TEST(ThreadChoice, RunsTheFasterCountBetweenProbes) {
  constexpr std::uint64_t P = ThreadChoice::kProbeSteps, S = ThreadChoice::kFirstStretch,
                          O = ThreadChoice::kOpeningStretch;
  ThreadChoice tc;
  std::vector<int> counts;
  // busy until step 2P + O + 2P + 4O (two threads 1.5x slower), then free (0.6x): probe (2 then 1), one
  // thread for O (the opening run), probe, one thread for 4O (the same choice), probe: two threads now, for S
  const std::uint64_t busy = 2 * P + O + 2 * P + 4 * O;
  const auto len = runs_of(tc, busy + 2 * P + S + 2 * P + 4 * S, 1.5, busy, 0.6, counts);
  const std::vector<int> want_counts{2, 1, 2, 1, 2, 1, 2, 1, 2};
  // then the same choice again: 4S
  const std::vector<std::uint64_t> want_len{P, P + O, P, P + 4 * O, P, P, S + P, P, 4 * S};
  EXPECT_EQ(counts, want_counts);
  EXPECT_EQ(len, want_len);
  EXPECT_EQ(tc.steps_at_one(), 4 * P + 5 * O);
  EXPECT_TRUE(tc.measuring());
}

TEST(ThreadChoice, NothingTimedOnOneThreadOrWhenOff) {
  ThreadChoice one;
  EXPECT_EQ(one.next(1), 1);
  EXPECT_FALSE(one.measuring());
  ThreadChoice restarted;  // a new max count starts the probes again, at that count
  std::vector<int> seen;
  runs_of(restarted, ThreadChoice::kProbeSteps + 1, 1.5, 0, 1.5, seen);
  EXPECT_EQ(restarted.next(3), 3);
  EXPECT_TRUE(restarted.measuring());
  setenv("AGGLO_THREAD_PROBE", "off", 1);
  ThreadChoice fixed;
  std::vector<int> counts;
  runs_of(fixed, 4 * ThreadChoice::kProbeSteps, 1.5, 0, 1.5, counts);
  unsetenv("AGGLO_THREAD_PROBE");
  EXPECT_EQ(counts, std::vector<int>{2});  // always the whole team
  EXPECT_FALSE(fixed.measuring());
}

// The first step of a probe can pay for the count's change once (the team's creation, its wake-up): a
// median of the probe's steps decides, not their sum. Here the first two-thread step takes 100 steps' time
// (sum: 100 + 31 x 0.6 > 32 x 1, so a sum would choose one thread), every later one 0.6 of one thread's.
TEST(ThreadChoice, AOneOffSlowStepDoesNotDecide) {
  ThreadChoice tc;
  std::vector<int> counts;
  for (std::uint64_t s = 0; s < 2 * ThreadChoice::kProbeSteps + 10; ++s) {
    const int t = tc.next(2);
    counts.push_back(t);
    tc.record(t == 1 ? 1.0 : s == 0 ? 100.0 : 0.6);
  }
  EXPECT_EQ(counts[2 * ThreadChoice::kProbeSteps - 1], 1);  // the one-thread probe
  EXPECT_EQ(counts.back(), 2);                               // then two threads
  // a step that is slower every time is not an outlier: 17 slow steps of 32 make the median slow
  ThreadChoice slow;
  counts.clear();
  for (std::uint64_t s = 0; s < 2 * ThreadChoice::kProbeSteps + 10; ++s) {
    const int t = slow.next(2);
    counts.push_back(t);
    slow.record(t == 1 ? 1.0 : s % 32 < 17 ? 1.5 : 0.6);
  }
  EXPECT_EQ(counts.back(), 1);
}
