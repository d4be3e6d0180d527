#include "agglo/dem/contact/lanes.hpp"

#include <atomic>

namespace agglo::dem::contact::lanes {

namespace {

bool cpu_has_wide_lanes() {
#if AGGLO_WIDE_LANES
  __builtin_cpu_init();
  return __builtin_cpu_supports("x86-64-v4");
#else
  return false;
#endif
}

std::atomic<bool>& wide_switch() {
  static std::atomic<bool> on{cpu_has_wide_lanes()};
  return on;
}

}  // namespace

bool wide_lanes() { return wide_switch().load(std::memory_order_relaxed); }

void set_wide_lanes(bool on) { wide_switch().store(on && cpu_has_wide_lanes(), std::memory_order_relaxed); }

}  // namespace agglo::dem::contact::lanes
