#include "agglo/run/reporter.hpp"

#include <chrono>
#include <cstdio>
#include <unistd.h>

#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::run {

namespace {
double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

TerminalReporter::~TerminalReporter() {
  std::lock_guard<std::mutex> lk(mutex_);
  clear_line();
}

void TerminalReporter::clear_line() {
  if (!shown_) return;
  std::fprintf(stderr, "\r%*s\r", static_cast<int>(width_), "");
  std::fflush(stderr);
  shown_ = false;
}

void TerminalReporter::progress(std::string_view label, double fraction, double sim_time_s) {
  if (quiet_ || !::isatty(2)) return;
  std::lock_guard<std::mutex> lk(mutex_);
  const double t = now_s();
  if (start_ < 0.0) start_ = last_ = t;
  const double elapsed = t - start_;
  if (elapsed < 2.0 || t - last_ < 0.25) return;
  last_ = t;
  // No ETA before any progress (e.g. a relaxation inside its first electrostatic solve): the time so far.
  const std::string eta = fraction > 1e-6 ? fmt::format("ETA {:.0f} s", elapsed * (1.0 - fraction) / fraction)
                                          : fmt::format("{:.0f} s so far", elapsed);
  const std::string line = sim_time_s > 0.0
                               ? fmt::format("{} {:5.1f}%  t={:.4g} s  {}   ", label, 100.0 * fraction, sim_time_s, eta)
                               : fmt::format("{} {:5.1f}%  {}   ", label, 100.0 * fraction, eta);
  width_ = std::max(width_, line.size());
  std::fprintf(stderr, "\r%s", line.c_str());
  std::fflush(stderr);
  shown_ = true;
}

void TerminalReporter::warning(std::string_view message) {
  std::lock_guard<std::mutex> lk(mutex_);
  clear_line();
  std::fprintf(stderr, "agglo: warning: %.*s\n", static_cast<int>(message.size()), message.data());
}

void TerminalReporter::info(std::string_view message) {
  std::lock_guard<std::mutex> lk(mutex_);
  clear_line();
  std::fprintf(stdout, "%.*s\n", static_cast<int>(message.size()), message.data());
  std::fflush(stdout);
}

void throw_if_cancelled(const CancelToken* token) {
  if (token && token->cancelled()) throw InterruptedError("interrupted");
}

}  // namespace agglo::run
