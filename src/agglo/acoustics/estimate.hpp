#pragma once
// Cost estimate of an acoustic DSMC run, from the validated case before the samples are drawn
// (core/estimate.hpp, docs/limits.md). With S = the sum of population.samples (constant during a
// run: merged samples are refilled, never appended), n_c = round(time.end / time.collision_dt)
// collision steps and m = collision_dt / motion_dt motion sub-steps (0 with integrator "none"):
//   steps   n_c S (1 + m) sample-steps (one collision pass and m motion steps per step)
//   memory  S x kSampleBytes (the structure of arrays of samples.hpp: 26 doubles, id and population,
//           cell index and order) + cells x (per-cell statistics, start/fill indices, error slot)
//           + the observations kept until the end (efficiency rows, size distributions, snapshot
//           rows) + the text of the largest CSV while it is written;
//           cells = cells_x cells_y cells_z as a double (never an integer overflow)
//   output  efficiency.csv, psd.csv, snapshots.csv rows at the writers' formats; snapshot rows are
//           S x snapshot_x_fraction per snapshot time (samples are uniform along x; a close estimate)
#include "agglo/acoustics/case_config.hpp"
#include "agglo/core/estimate.hpp"

namespace agglo::acoustics {

Estimate acoustic_estimate(const AcousticCase& c);

}  // namespace agglo::acoustics
