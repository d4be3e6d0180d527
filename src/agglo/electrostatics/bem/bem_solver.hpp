#pragma once
// BEM: collocation boundary elements + GMRES (direct or FMM matvec), docs/model.md §B.2 item 2;
// method and measured accuracy in docs/bem_fmm.md. Input is checked by validate_spheres()
// (InvalidSpheres); invalid options throw agglo::ConfigError from make_bem_solver; GMRES not
// converging throws agglo::NumericalError.
#include <memory>

#include "agglo/electrostatics/registry.hpp"

namespace agglo::es {

namespace bem {
// Fewest patches per sphere: the 12 vertices of the icosahedron, the coarsest surface sampling any
// solver accepts (SolverOptions::patches_per_sphere).
inline constexpr int kMinPatchesPerSphere = 12;
}  // namespace bem

inline constexpr std::string_view kBemSolver = "bem";

std::unique_ptr<Solver> make_bem_solver(const SolverOptions& opt);

// Its entry in the solver registry (registry.hpp), with its cost model.
SolverType bem_solver_type();

}  // namespace agglo::es
