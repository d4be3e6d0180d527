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
#include "agglo/acoustics/engine.hpp"
#include "agglo/acoustics/run.hpp"
#include "agglo/io/checkpoint.hpp"

namespace agglo::acoustics {

void save_engine(const Engine& e, io::CheckpointWriter& w);
// Overwrites the state of an engine built from the same settings; ConfigError when the payload does
// not fit them (other sample or cell count).
void load_engine(Engine& e, io::CheckpointReader& r);

// The observations buffered while the run goes on (not the closing fields: final counts, statistics).
void save_observations(const AcousticObservations& o, io::CheckpointWriter& w);
void load_observations(AcousticObservations& o, io::CheckpointReader& r);

}  // namespace agglo::acoustics
