#include "agglo/core/thread_choice.hpp"

#include <algorithm>
#include <cstdlib>
#include <string_view>

namespace agglo {

void ThreadChoice::start(int max_threads) {
  const char* probe = std::getenv("AGGLO_THREAD_PROBE");
  max_ = max_threads;
  fixed_ = probe != nullptr && std::string_view(probe) == "off";
  chosen_ = 0;
  phase_ = Phase::probe_many;
  left_ = kProbeSteps;
  stretch_ = kOpeningStretch;
}

int ThreadChoice::next(int max_threads) {
  if (max_threads != max_) start(max_threads);
  int count = max_;
  if (measuring() && phase_ != Phase::probe_many) count = phase_ == Phase::probe_one ? 1 : chosen_;
  if (max_ > 1) ++(count == max_ ? at_max_ : at_one_);
  return count;
}

int ThreadChoice::begin(int max_threads) {
  const int count = next(max_threads);
  if (measuring()) began_ = std::chrono::steady_clock::now();
  return count;
}

void ThreadChoice::end() {
  if (measuring()) record(std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count());
}

namespace {

// The median of a probe's step times (the upper one of the two middle values).
double median(std::array<double, ThreadChoice::kProbeSteps> t) {
  auto mid = t.begin() + t.size() / 2;
  std::nth_element(t.begin(), mid, t.end());
  return *mid;
}

}  // namespace

void ThreadChoice::record(double seconds) {
  if (!measuring()) return;
  if (phase_ == Phase::probe_many) wall_many_[kProbeSteps - left_] = seconds;
  if (phase_ == Phase::probe_one) wall_one_[kProbeSteps - left_] = seconds;
  if (--left_ > 0) return;
  if (phase_ == Phase::probe_many) {
    phase_ = Phase::probe_one;
    left_ = kProbeSteps;
  } else if (phase_ == Phase::probe_one) {
    const int faster = median(wall_many_) < median(wall_one_) ? max_ : 1;
    // the same count again: a longer run before the next probe; the other count: the first length again
    if (chosen_ != 0) stretch_ = faster == chosen_ ? std::min(4 * stretch_, kMaxStretch) : kFirstStretch;
    chosen_ = faster;
    phase_ = Phase::run;
    left_ = stretch_;
  } else {
    phase_ = Phase::probe_many;
    left_ = kProbeSteps;
  }
}

}  // namespace agglo
