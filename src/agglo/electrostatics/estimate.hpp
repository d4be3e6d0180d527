#pragma once
// Cost estimate: memory, output and steps of an electrostatic solve, from the sphere list before the
// solver allocates anything (core/estimate.hpp, docs/limits.md). Close estimates built from the arrays each
// solver holds (N spheres, P = patches_per_sphere):
//   coulomb   O(N): the spheres and the result
//   spectral  one pair record per sphere pair, N (N - 1) / 2, each with the Wigner rotation of its
//             degree L_pair (about L_pair^3 doubles; L_pair chosen as the solver does, spectral/degree.hpp),
//             plus O(N (L+1)^2) coefficient vectors and the GMRES basis
//   bem       per patch (N P of them): (restart + 1) GMRES basis vectors, restart = min(max_iterations,
//             100), plus kBemArrayBytesPerPatch of patch, operator, FMM and surface arrays
// Steps of a static solve are interaction evaluations, bounded with every allowed GMRES iteration
// (max_iterations): coulomb N^2; spectral max_iterations x sum over pairs of (L_pair + 1)^3 (one
// rotation-based translation); bem max_iterations x N P x (N P with the direct matvec, 27 x
// fmm_leaf_size near-field patches with the FMM).
// Output: forces.csv (one row per sphere), surface.vtu (the solver's surface samples).
// The degree L of the spectral solver needs every pair: above kExactPairLimit pairs the estimate
// uses L_pair = 2 (a lower bound, still enough to refuse a case of 1e5 spheres).
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

// The electrostatics command: steps = spheres (one static solve), memory = solver + surface output
// kept in memory, output = forces.csv + surface.vtu + small JSON files; without surface.vtu when
// `surface` is false (output.surface).
Estimate static_solve_estimate(const SolverOptions& opt, const Problem& p, bool surface = true);

}  // namespace agglo::es
