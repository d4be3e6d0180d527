#pragma once
// Thread count of the DSMC step on a shared machine (issue 27 item 3: threads help, never hurt).
// A step's result does not depend on its thread count (engine.hpp), only its wall time does: on a
// machine whose cores are busy with other work, T threads that must meet at the step's barriers can
// take longer than one thread alone. The engine therefore measures both, in alternation:
//   probe   kProbeSteps steps at T threads, then kProbeSteps at one thread (wall time, steady clock);
//   run     the faster count (T only when its probe took less time) for a stretch of steps that starts
//           at kFirstStretch and grows 4× per probe, up to kMaxStretch, while the probes keep choosing
//           the same count; then probe again.
// The cost is the probes of the slower count: kProbeSteps of every kFirstStretch + 2 kProbeSteps steps
// at first (3 %), of every kMaxStretch + 2 kProbeSteps later (0.2 %), each slower by the ratio of the
// two counts' step times (a 4 s baseline of 80 000 steps probes 6 times). With T = 1 (or `AGGLO_THREAD_PROBE=off` in the environment: always T,
// for measuring the fixed count) nothing is measured.
#include <cstdint>

namespace agglo::acoustics {

class ThreadChoice {
 public:
  static constexpr std::uint64_t kProbeSteps = 32, kFirstStretch = 1024, kMaxStretch = 16384;

  // Threads for the next step, at most max_threads (a change of max_threads restarts the probes).
  int next(int max_threads);
  // Wall time [s] of the step just taken with next()'s count.
  void record(double seconds);
  // Whether record() needs the step's wall time (false when nothing is being compared).
  bool measuring() const { return max_ > 1 && !fixed_; }
  std::uint64_t steps_at_max() const { return steps_at_max_; }  // steps taken with max_threads (> 1)
  std::uint64_t steps_at_one() const { return steps_at_one_; }  // steps taken with one thread instead

 private:
  enum class Phase { probe_many, probe_one, run };
  void restart(int max_threads);
  int max_ = 0;
  bool fixed_ = false;
  Phase phase_ = Phase::probe_many;
  int chosen_ = 0;              // count of the run phase (0: no probe finished yet)
  std::uint64_t left_ = 0;      // steps left in the current phase
  std::uint64_t stretch_ = kFirstStretch;
  double t_many_ = 0.0, t_one_ = 0.0;  // probe wall times [s]
  std::uint64_t steps_at_max_ = 0, steps_at_one_ = 0;
};

}  // namespace agglo::acoustics
