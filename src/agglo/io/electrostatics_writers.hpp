#pragma once
// Files of a static electrostatic solve (agglo electrostatics): forces.csv (id,fx,fy,fz,tx,ty,tz in
// N and N m), energy.json, stats.json (solver statistics), surface.vtu (surface charge, ParaView).
#include <string>

#include <nlohmann/json.hpp>

#include "agglo/electrostatics/solver.hpp"
#include "agglo/io/output_dir.hpp"

namespace agglo::io {

// Solver statistics as written to stats.json.
nlohmann::json solve_stats(const es::Solver& solver, const es::Problem& p, const es::Solution& sol);

void write_electrostatics(const OutputDir& out, const es::Solver& solver, const es::Problem& p,
                          const es::Solution& sol);

}  // namespace agglo::io
