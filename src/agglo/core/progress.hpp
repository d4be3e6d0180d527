#pragma once
// Progress line on stderr ("  42% t=1.2e-03 s ETA 3 s"), shown only for runs longer than ~2 s,
// only when stderr is a terminal, and never with --quiet. Thread-safe to call from one thread.
#include <chrono>
#include <string>

namespace agglo {

class Progress {
 public:
  Progress(std::string label, bool enabled);
  ~Progress();
  void update(double fraction, double sim_time_s);
  void finish();
  static bool& quiet();  // global --quiet switch

 private:
  std::string label_;
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace agglo
