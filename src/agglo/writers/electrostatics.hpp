#pragma once
// Results of a static electrostatic solve (agglo electrostatics): forces.csv (id, fx, fy, fz, tx, ty, tz
// in N and N m), energy.json, stats.json (solver statistics), surface.vtu (surface charge, ParaView), and
// results.nc: the particle table (forces_table; dims particle, xyz: also position [m], radius [m],
// charge [C], permittivity [1]), 0-d energy [J] and stats.json's numbers.
#include <string>

#include <nlohmann/json.hpp>

#include "agglo/electrostatics/solver.hpp"
#include "agglo/io/dataset.hpp"
#include "agglo/io/output_dir.hpp"
#include "agglo/io/table.hpp"

namespace agglo::writers {

// Solver statistics as written to stats.json.
nlohmann::json solve_stats(const es::Solver& solver, const es::Problem& p, const es::Solution& sol);

// forces.csv and the per-particle variables of results.nc.
io::Table forces_table(const es::Problem& p, const es::Solution& sol);

// forces.csv, energy.json, stats.json and, if `surface` (output.surface), surface.vtu.
void write_electrostatics(const OutputDir& out, const es::Solver& solver, const es::Problem& p,
                          const es::Solution& sol, bool surface = true);

io::Dataset electrostatics_dataset(const es::Solver& solver, const es::Problem& p, const es::Solution& sol);

}  // namespace agglo::writers
