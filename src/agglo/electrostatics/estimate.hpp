#pragma once
// Cost estimate: memory, output and steps of an electrostatic solve, from the sphere list before the
// solver allocates anything (core/estimate.hpp, docs/limits.md). Close estimates built from the arrays each
// solver holds, each solver type's cost model (registry.hpp; coulomb_solver.hpp, spectral/cost.cpp,
// bem/cost.cpp): bytes held, interaction evaluations of one solve bounded with every allowed GMRES
// iteration (max_iterations), surface samples, and its measured seconds per interaction.
// Output: forces.csv (one row per sphere), surface.vtu (the solver's surface samples).
#include "agglo/core/estimate.hpp"
#include "agglo/electrostatics/solver.hpp"

namespace agglo::es {

// Bytes the solver `opt.solver` holds for problem `p` (the solve, not the output).
double solver_memory_bytes(const SolverOptions& opt, const Problem& p);

// Interaction evaluations of one solve (see above).
double solver_steps(const SolverOptions& opt, const Problem& p);

// Lower bounds of the steps and memory from the number of spheres alone (every pair at the smallest
// degree), cheap enough to check before the O(N^2) validation of the sphere positions.
Estimate static_solve_lower_bound(const SolverOptions& opt, double spheres, bool surface = true);

// Surface samples the solver returns for output (surface.vtu) with `spheres` spheres.
double surface_samples(const SolverOptions& opt, double spheres);

// Wall seconds of one interaction on one thread (the --dry-run time estimate).
double seconds_per_interaction(const SolverOptions& opt);

// False for a solver of point charges (no induced charges whatever the permittivities).
bool induces_charges(const SolverOptions& opt);

// The electrostatics command: steps = spheres (one static solve), memory = solver + surface output
// kept in memory, output = forces.csv + surface.vtu + small JSON files; without surface.vtu when
// `surface` is false (output.surface).
Estimate static_solve_estimate(const SolverOptions& opt, const Problem& p, bool surface = true);

}  // namespace agglo::es
