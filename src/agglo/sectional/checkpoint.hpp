#pragma once
// Exact restart of a sectional run (docs/restart.md): what the next step reads — the time, the number
// concentration of every pivot, the stepper's next step size and statistics — and the run's buffered
// observations (acoustics/checkpoint.hpp). The grid, kernel table and initial projection follow from the
// case, which the checkpoint's config hash ties to it. Checkpoints are taken at output times only (the
// stepper ends a step exactly at each output time, so extra stops would change the solution).
#include "agglo/acoustics/run.hpp"
#include "agglo/io/checkpoint.hpp"
#include "agglo/sectional/solver.hpp"

namespace agglo::sectional {

void save_solver(const SectionalSolver& s, io::CheckpointWriter& w);
// Overwrites the state of a solver built from the same case; ConfigError when the pivot count differs.
void load_solver(SectionalSolver& s, io::CheckpointReader& r);

}  // namespace agglo::sectional
