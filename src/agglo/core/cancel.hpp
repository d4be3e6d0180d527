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
//
// The same polls keep a progress report alive inside a long solve: a HeartbeatScope installs a function
// that poll_cancel() calls on the calling thread (the pre-impact relaxation reports its progress from it,
// so that its first electrostatic solve, tens of seconds with the BEM, is not silent). The function must
// be cheap or throttle itself (heartbeat_due).
#include <atomic>
#include <chrono>
#include <functional>

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
inline thread_local const std::function<void()>* t_heartbeat = nullptr;
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

// For the span of one file write: keeps the calling thread's token while the run is live, so that the
// writer's polls stop a long write (io/output_dir.cpp), and removes it when the run was already
// cancelled when the write began, so that the results flushed after an interruption (the history so far,
// the snapshots, results.nc marked incomplete) are written whole.
class WriteCancelScope {
 public:
  WriteCancelScope() noexcept : saved_(detail::t_cancel_token) {
    if (saved_ && saved_->cancelled()) detail::t_cancel_token = nullptr;
  }
  ~WriteCancelScope() { detail::t_cancel_token = saved_; }
  WriteCancelScope(const WriteCancelScope&) = delete;
  WriteCancelScope& operator=(const WriteCancelScope&) = delete;

 private:
  const CancelToken* saved_;
};

// Installs `beat` as the calling thread's heartbeat for the scope's lifetime (null: none).
class HeartbeatScope {
 public:
  explicit HeartbeatScope(const std::function<void()>* beat) noexcept : saved_(detail::t_heartbeat) {
    detail::t_heartbeat = beat;
  }
  ~HeartbeatScope() { detail::t_heartbeat = saved_; }
  HeartbeatScope(const HeartbeatScope&) = delete;
  HeartbeatScope& operator=(const HeartbeatScope&) = delete;

 private:
  const std::function<void()>* saved_;
};

// True at most once per `interval` (a heartbeat's throttle; `last` holds the time of the last true).
inline bool heartbeat_due(std::chrono::steady_clock::time_point& last,
                          std::chrono::steady_clock::duration interval = std::chrono::milliseconds(100)) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last < interval) return false;
  last = now;
  return true;
}

// Throws InterruptedError("interrupted") when the calling thread's token is set; calls its heartbeat.
inline void poll_cancel() {
  const CancelToken* t = detail::t_cancel_token;
  if (t && t->cancelled()) throw InterruptedError("interrupted");
  if (const auto* beat = detail::t_heartbeat) (*beat)();
}

}  // namespace agglo
