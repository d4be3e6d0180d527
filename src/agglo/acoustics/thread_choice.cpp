#include "agglo/acoustics/thread_choice.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace agglo::acoustics {

void ThreadChoice::restart(int max_threads) {
  max_ = max_threads;
  const char* env = std::getenv("AGGLO_THREAD_PROBE");
  fixed_ = env != nullptr && std::strcmp(env, "off") == 0;
  phase_ = Phase::probe_many;
  left_ = kProbeSteps;
  stretch_ = kFirstStretch;
  chosen_ = 0;  // none yet
  t_many_ = t_one_ = 0.0;
}

int ThreadChoice::next(int max_threads) {
  if (max_threads != max_) restart(max_threads);
  const int t = !measuring() ? max_ : phase_ == Phase::probe_many ? max_ : phase_ == Phase::probe_one ? 1 : chosen_;
  if (max_ > 1) ++(t == max_ ? steps_at_max_ : steps_at_one_);
  return t;
}

void ThreadChoice::record(double seconds) {
  if (!measuring()) return;
  if (phase_ == Phase::probe_many) t_many_ += seconds;
  if (phase_ == Phase::probe_one) t_one_ += seconds;
  if (--left_ > 0) return;
  switch (phase_) {
    case Phase::probe_many:
      phase_ = Phase::probe_one;
      left_ = kProbeSteps;
      break;
    case Phase::probe_one: {
      const int best = t_many_ < t_one_ ? max_ : 1;
      // the same choice as before: a longer stretch before the next probe; a new one: the first stretch
      stretch_ = best == chosen_ ? std::min(4 * stretch_, kMaxStretch) : kFirstStretch;
      chosen_ = best;
      phase_ = Phase::run;
      left_ = stretch_;
      break;
    }
    case Phase::run:
      phase_ = Phase::probe_many;
      left_ = kProbeSteps;
      t_many_ = t_one_ = 0.0;
      break;
  }
}

}  // namespace agglo::acoustics
