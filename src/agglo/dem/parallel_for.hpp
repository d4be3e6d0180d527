#pragma once
// f(k) for k in [0, n): an OpenMP parallel loop (static schedule) above kParallelThreshold items,
// serial below it (entering a parallel region costs more than small loops). Every k is handled by
// exactly one thread, so results do not depend on the thread count when f(k) writes only slot k.
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

template <class F>
void parallel_for(std::int64_t n, const F& f) {
  if (n > kParallelThreshold) {
#pragma omp parallel for schedule(static)
    for (std::int64_t k = 0; k < n; ++k) f(k);
  } else {
    for (std::int64_t k = 0; k < n; ++k) f(k);
  }
}

// Whether f(k) is true for any k in [0, n), f called for every k (as parallel_for; an OR reduction, so the
// answer does not depend on the thread count).
template <class F>
bool parallel_any(std::int64_t n, const F& f) {
  int any = 0;
  if (n > kParallelThreshold) {
#pragma omp parallel for schedule(static) reduction(| : any)
    for (std::int64_t k = 0; k < n; ++k) any |= f(k) ? 1 : 0;
  } else {
    for (std::int64_t k = 0; k < n; ++k) any |= f(k) ? 1 : 0;
  }
  return any != 0;
}

}  // namespace agglo::dem
