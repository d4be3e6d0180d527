#include "agglo/core/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace agglo {

bool& Progress::quiet() {
  static bool q = false;
  return q;
}

Progress::Progress(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled && !quiet() && ::isatty(2)),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

Progress::~Progress() { finish(); }

void Progress::update(double fraction, double sim_time_s) {
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  double el = std::chrono::duration<double>(now - start_).count();
  if (el < 2.0 || std::chrono::duration<double>(now - last_).count() < 0.25) return;
  last_ = now;
  double eta = fraction > 1e-6 ? el * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r%s %5.1f%%  t=%.4g s  ETA %.0f s   ", label_.c_str(), 100.0 * fraction, sim_time_s, eta);
  std::fflush(stderr);
  shown_ = true;
}

void Progress::finish() {
  if (shown_) {
    std::fprintf(stderr, "\r%*s\r", 60 + static_cast<int>(label_.size()), "");
    std::fflush(stderr);
    shown_ = false;
  }
}

}  // namespace agglo
