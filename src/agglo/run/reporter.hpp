#pragma once
// Where progress, warnings and one-line results of a run go. Engines and the run pipeline never
// print: they call a Reporter, and each front end directs it (the CLI to the terminal, a Python
// module to a callback, an MPI rank to rank 0). Calls may come from any thread; implementations
// serialise them.
#include <mutex>
#include <string>
#include <string_view>

#include "agglo/core/cancel.hpp"

namespace agglo::run {

class Reporter {
 public:
  virtual ~Reporter() = default;
  // Fraction done in [0, 1] of the task `label`, and its simulated time [s] (0 when not meaningful).
  virtual void progress(std::string_view label, double fraction, double sim_time_s) = 0;
  // A warning about the run (not an error): one line, no trailing newline.
  virtual void warning(std::string_view message) = 0;
  // A result line for the user (e.g. "v_crit = 0.1775 m/s").
  virtual void info(std::string_view message) = 0;
};

// Discards everything.
class SilentReporter final : public Reporter {
 public:
  void progress(std::string_view, double, double) override {}
  void warning(std::string_view) override {}
  void info(std::string_view) override {}
};

// The terminal: a progress line on stderr (only on a terminal, only for tasks longer than ~2 s, never
// when quiet), warnings on stderr as "agglo: warning: ...", results on stdout.
class TerminalReporter final : public Reporter {
 public:
  explicit TerminalReporter(bool quiet) : quiet_(quiet) {}
  ~TerminalReporter() override;
  void progress(std::string_view label, double fraction, double sim_time_s) override;
  void warning(std::string_view message) override;
  void info(std::string_view message) override;

 private:
  void clear_line();
  bool quiet_;
  std::mutex mutex_;
  bool shown_ = false;
  double start_ = -1.0, last_ = -1.0;
  std::size_t width_ = 0;
};

// Cooperative cancellation (core/cancel.hpp): set from a signal handler or another thread, polled by runs
// between steps, by the ensemble runner between jobs and, through a CancelScope, by the engines.
using CancelToken = agglo::CancelToken;

// Throws InterruptedError when `token` is set (no-op for a null token).
void throw_if_cancelled(const CancelToken* token);

}  // namespace agglo::run
