// The BEM solver's type and cost model (registry.hpp, estimate.hpp): per patch (N P of them,
// P = patches_per_sphere), (restart + 1) GMRES basis vectors, restart = min(max_iterations, 100),
// plus kArrayBytesPerPatch of patch, operator, FMM and surface arrays; work max_iterations x N P x
// (N P with the direct matvec, 27 x fmm_leaf_size near-field patches with the FMM).
#include <algorithm>

#include "agglo/electrostatics/bem/bem_solver.hpp"

namespace agglo::es {

namespace {

// BEM arrays per patch besides the GMRES basis: patch set (92 B), operator buffers (88 B), solver
// vectors (about 100 B), FMM points, expansions and lists (about 150 B), surface samples twice
// (the solver's and the writer's copy, 2 x 80 B).
constexpr double kArrayBytesPerPatch = 600.0;
// One thread: with the FMM 1.3e-8 s per near-field interaction (the 30-sphere cluster of
// tests/cli/interrupt_phases.sh, 2000 patches: 272 s for 2.07e10), direct 1.3e-9 s per interaction
// (400 patches: 38 s for 2.88e10).
constexpr double kFmmSeconds = 1.3e-8;

double patch_bytes(const SolverOptions& opt) {
  return 8.0 * (std::min(opt.max_iterations, 100) + 1.0) + kArrayBytesPerPatch;
}

double bem_memory_lower_bound(const SolverOptions& opt, double spheres) {
  return spheres * opt.patches_per_sphere * patch_bytes(opt);
}

double bem_memory_bytes(const SolverOptions& opt, const Problem& p) {
  return bem_memory_lower_bound(opt, static_cast<double>(p.spheres.size()));
}

bool direct(const SolverOptions& opt) { return opt.matvec == "direct"; }

double bem_interactions(const SolverOptions& opt, const Problem& p) {
  const double patches = static_cast<double>(p.spheres.size()) * opt.patches_per_sphere;
  return opt.max_iterations * patches * (direct(opt) ? patches : 27.0 * opt.fmm_leaf_size);
}

}  // namespace

SolverType bem_solver_type() {
  return {.name = kBemSolver,
          .make = &make_bem_solver,
          .memory_bytes = &bem_memory_bytes,
          .memory_lower_bound = &bem_memory_lower_bound,
          .interactions = &bem_interactions,
          .samples_per_sphere = [](const SolverOptions& opt) { return static_cast<double>(opt.patches_per_sphere); },
          .seconds_per_interaction = [](const SolverOptions& opt) { return direct(opt) ? kPointChargeSeconds : kFmmSeconds; },
          .cost_keys = {"patches_per_sphere"}};
}

}  // namespace agglo::es
