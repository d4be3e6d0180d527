#pragma once
// results.nc of `agglo electrostatics` as labelled arrays (io/dataset.hpp): dims particle (coordinate
// `particle`, forces.csv's id) and xyz: position [m], radius [m] (electrostatic radius), charge [C],
// permittivity [1], force [N] and torque [N m] (forces.csv's fx..tz as (particle, xyz)); 0-d energy [J]
// (energy.json) and stats.json's numbers (iterations, residual, time_s, degree, particles, smallest_gap_m).
#include "agglo/electrostatics/solver.hpp"
#include "agglo/io/dataset.hpp"

namespace agglo::io {

Dataset electrostatics_dataset(const es::Solver& solver, const es::Problem& p, const es::Solution& sol);

}  // namespace agglo::io
