#pragma once
// f(k) for k in [0, n): an OpenMP parallel loop (static schedule) above kParallelThreshold items,
// serial below it (entering a parallel region costs more than small loops). Every k is handled by
// exactly one thread, so results do not depend on the thread count when f(k) writes only slot k.
#include <algorithm>
#include <cstdint>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace agglo::dem {

inline constexpr std::int64_t kParallelThreshold = 4096;  // pairs or particles

// True when parallel_for(n, ...) runs on more than one thread.
inline bool runs_parallel(std::int64_t n) {
#ifdef _OPENMP
  return n > kParallelThreshold && omp_get_max_threads() > 1;
#else
  return false;
#endif
}

// Threads a parallel region would use (1 without OpenMP).
inline int max_threads() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

// This thread's number in its team and the team's size (0 and 1 outside a parallel region or without OpenMP).
inline int thread_id() {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}
inline int team_size() {
#ifdef _OPENMP
  return omp_get_num_threads();
#else
  return 1;
#endif
}

// The thread count of the parallel regions this thread starts, set to `count` for the guard's lifetime
// (omp_set_num_threads; restored by the destructor, also when an exception leaves the scope).
class TeamSize {
 public:
  explicit TeamSize(int count) : saved_(max_threads()) { set(count); }
  ~TeamSize() { set(saved_); }
  TeamSize(const TeamSize&) = delete;
  TeamSize& operator=(const TeamSize&) = delete;

 private:
  static void set([[maybe_unused]] int count) {
#ifdef _OPENMP
    omp_set_num_threads(count);
#endif
  }
  int saved_;
};

// f(k) for k in [0, count), in parallel when the loop handles more than kParallelThreshold items (`work`).
template <class F>
void parallel_loop(std::int64_t work, std::int64_t count, const F& f) {
  if (work > kParallelThreshold) {
#pragma omp parallel for schedule(static)
    for (std::int64_t k = 0; k < count; ++k) f(k);
  } else {
    for (std::int64_t k = 0; k < count; ++k) f(k);
  }
}

template <class F>
void parallel_for(std::int64_t n, const F& f) {
  parallel_loop(n, n, f);
}

// The ranges [k c, min(n, (k + 1) c)) of [0, n) in chunks of c items: f(begin, end) on each, in parallel as
// parallel_for would be for n items.
template <class F>
void parallel_for_ranges(std::int64_t n, std::int64_t c, const F& f) {
  parallel_loop(n, (n + c - 1) / c, [&](std::int64_t k) { f(k * c, std::min(n, (k + 1) * c)); });
}

// Whether f(begin, end) is true for any of those ranges, f called on every one (an OR reduction, so the
// answer does not depend on the thread count).
template <class F>
bool parallel_any_ranges(std::int64_t n, std::int64_t c, const F& f) {
  const std::int64_t chunks = (n + c - 1) / c;
  auto range = [&](std::int64_t k) { return f(k * c, std::min(n, (k + 1) * c)) ? 1 : 0; };
  int any = 0;
  if (n > kParallelThreshold) {
#pragma omp parallel for schedule(static) reduction(| : any)
    for (std::int64_t k = 0; k < chunks; ++k) any |= range(k);
  } else {
    for (std::int64_t k = 0; k < chunks; ++k) any |= range(k);
  }
  return any != 0;
}

}  // namespace agglo::dem
