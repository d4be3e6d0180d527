#pragma once
// Thread count of a parallel time step on a shared machine (issue 27 item 3: threads help, never hurt).
// For an engine whose step gives the same bits at any thread count (the DEM and the DSMC), only the
// wall time depends on the count: on a machine whose cores are busy with other work, T threads that meet
// at a step's barriers can take longer than one thread alone. So both are timed, in turn:
//   probe   kProbeSteps steps at T threads, then kProbeSteps at one thread (wall time, steady clock);
//   run     the faster count (T only when the median step of its probe took less time: a median, so that
//           a step slow once, such as the first after a change of count, does not decide) for a stretch of
//           steps that starts at kFirstStretch (kOpeningStretch after the very first probe) and grows 4x per
//           probe, up to kMaxStretch, while the probes keep choosing the same count; then probe again.
// The cost is the probes of the slower count: kProbeSteps of every kFirstStretch + 2 kProbeSteps steps at
// first (3 %), of every kMaxStretch + 2 kProbeSteps later (0.2 %), each slower by the ratio of the two
// counts' step times. With T = 1, or `AGGLO_THREAD_PROBE=off` in the environment (always T: for measuring
// the fixed count), nothing is timed. Used by the DSMC step
// (acoustics/engine.hpp) and the DEM step (dem/dem_system.hpp).
#include <array>
#include <chrono>
#include <cstdint>

namespace agglo {

class ThreadChoice {
 public:
  static constexpr std::uint64_t kProbeSteps = 32, kFirstStretch = 1024, kMaxStretch = 16384;
  // The run after the very first probe: short, so that a first probe misled by the start (the team's threads
  // not yet spread over the cores; two-thread DEM blocks ran on one thread in 2 or 3 of 6 runs on idle cores with
  // a first run of kFirstStretch) is corrected soon.
  static constexpr std::uint64_t kOpeningStretch = 128;

  // Threads for the next step: max_threads or 1 (a change of max_threads starts the probes again).
  int next(int max_threads);
  // Wall time [s] of the step just taken with next()'s count.
  void record(double seconds);
  // Whether record() wants the step's wall time (false when nothing is compared).
  bool measuring() const { return max_ > 1 && !fixed_; }
  // next() with the step's clock: begin() before the step, end() after it records its wall time when
  // measuring (what the engines call; next and record are the parts, driven by the tests' synthetic times).
  int begin(int max_threads);
  void end();
  std::uint64_t steps_at_max() const { return at_max_; }  // steps taken with max_threads (> 1)
  std::uint64_t steps_at_one() const { return at_one_; }  // steps taken with one thread instead

 private:
  enum class Phase { probe_many, probe_one, run };
  void start(int max_threads);
  int max_ = 0, chosen_ = 0;  // chosen_: count of the run phase (0 before the first probe ends)
  bool fixed_ = false;
  Phase phase_ = Phase::probe_many;
  std::uint64_t left_ = 0, stretch_ = kFirstStretch;  // steps left in the phase; length of the next run
  std::array<double, kProbeSteps> wall_many_{}, wall_one_{};  // the probes' step times [s]
  std::uint64_t at_max_ = 0, at_one_ = 0;
  std::chrono::steady_clock::time_point began_{};  // begin()'s time when measuring
};

}  // namespace agglo
