#pragma once
// Cooperative cancellation of a run (Ctrl-C, SIGTERM, Python's KeyboardInterrupt), seen by every layer.
//
// A CancelToken is set from a signal handler or another thread. The front ends hand it to the run
// pipeline (run::RunContext::cancel), which installs it for the thread that runs the engines with a
// CancelScope (run::execute, each job thread of an ensemble, the Python worker thread). Engines that
// may spend long between their step boundaries poll it with poll_cancel(): the DEM relaxation every
// step, the electrostatic solvers in their set-up loops and after every GMRES operator application, the
// structure builders per placement (run::plan installs the token while a case is parsed, which builds).
// poll_cancel() is an atomic load behind a thread-local pointer (a few ns); it is never called inside
// an OpenMP parallel region (an exception must not leave one), so a solve stops at most one operator
// application after the token is set. A thread without a scope (tests, library calls) never stops.
#include <atomic>

#include "agglo/core/error.hpp"

namespace agglo {

// Lock-free, so setting it is async-signal-safe.
class CancelToken {
 public:
  void cancel() noexcept { flag_.store(true, std::memory_order_relaxed); }
  bool cancelled() const noexcept { return flag_.load(std::memory_order_relaxed); }
  void reset() noexcept { flag_.store(false, std::memory_order_relaxed); }

 private:
  std::atomic<bool> flag_{false};
};

namespace detail {
inline thread_local const CancelToken* t_cancel_token = nullptr;
}  // namespace detail

// The token installed for the calling thread (null: none).
inline const CancelToken* current_cancel_token() noexcept { return detail::t_cancel_token; }

// Installs `token` for the calling thread for the scope's lifetime (null keeps the one installed).
class CancelScope {
 public:
  explicit CancelScope(const CancelToken* token) noexcept : saved_(detail::t_cancel_token) {
    if (token) detail::t_cancel_token = token;
  }
  ~CancelScope() { detail::t_cancel_token = saved_; }
  CancelScope(const CancelScope&) = delete;
  CancelScope& operator=(const CancelScope&) = delete;

 private:
  const CancelToken* saved_;
};

// Throws InterruptedError("interrupted") when the calling thread's token is set.
inline void poll_cancel() {
  const CancelToken* t = detail::t_cancel_token;
  if (t && t->cancelled()) throw InterruptedError("interrupted");
}

}  // namespace agglo
