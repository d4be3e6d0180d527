#pragma once
// Exact restart of an acoustic run (docs/restart.md): the state that the next step of the engine and
// the run loop read, written to and read back from a checkpoint payload (io/checkpoint.hpp) in a fixed
// order, field by field (no struct padding, so equal states give equal bytes).
//   engine: step counter (the random streams are keyed by it), every array of the samples in their
//           present order (state, derived caches and the wave-phase cache of the exact integrator: a
//           recomputed cache would round differently), cells and sample order, collision statistics
//           (Nanbu guard and binned majorant maxima, energy lost and compensated), the binned
//           selection's groups of every cell (members, bounds, versions, majorant cache, previous
//           collisions) and its scratch index;
//   run:    the buffered observations (efficiency rows, PSD records, snapshot rows, initial counts,
//           PSD bins, run.log text so far, last time with pure droplets).
// Settings are not saved: the checkpoint is tied to the resolved config by its hash.
#include <cmath>

#include "agglo/acoustics/engine.hpp"
#include "agglo/acoustics/run.hpp"
#include "agglo/io/checkpoint.hpp"

namespace agglo::acoustics {

// When a run writes checkpoints (RunHooks::checkpoint_interval): at the first state at or after each
// multiple of the interval, and on request (interruption, end) unless the state of that time is written.
class CheckpointSchedule {
 public:
  // interval 0: never. t: time of the start state; resumed: that state is the checkpoint in place.
  CheckpointSchedule(double interval, double t, bool resumed)
      : interval_(interval), period_(period(t)), written_(resumed), last_(t) {}
  // True when the state at time t [s] is to be written (then call written(t)); force: interruption or end.
  bool due(double t, bool force) {
    if (interval_ <= 0.0) return false;
    if (period(t) > period_) {
      period_ = period(t);
      return true;
    }
    return force && !(written_ && last_ == t);
  }
  void written(double t) {
    written_ = true;
    last_ = t;
  }

 private:
  // Index of the interval holding t (a relative 1e-9 absorbs the rounding of step * dt).
  double period(double t) const { return interval_ > 0.0 ? std::floor(t / interval_ * (1.0 + 1e-9)) : 0.0; }
  double interval_;
  double period_;
  bool written_;
  double last_;
};

void save_engine(const Engine& e, io::CheckpointWriter& w);
// Overwrites the state of an engine built from the same settings; ConfigError when the payload does
// not fit them (other sample or cell count).
void load_engine(Engine& e, io::CheckpointReader& r);

// The observations buffered while the run goes on (not the closing fields: final counts, statistics).
void save_observations(const AcousticObservations& o, io::CheckpointWriter& w);
void load_observations(AcousticObservations& o, io::CheckpointReader& r);

}  // namespace agglo::acoustics
