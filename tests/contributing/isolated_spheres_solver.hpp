#pragma once
// Solver "isolated": every sphere alone in the applied field, blind to the others (a lower-bound
// reference, exact for one sphere of kappa_p = kappa_0):
//   F_i = q_i E_ext [N],  torque 0,
//   U = sum_i q_i^2 / (8 pi eps0 kappa_0 a_i) - 1/2 sum_i q_i E_ext . x_i   [J]
// Surface: one point sample per sphere, at its centre (no mesh).
#include <memory>

#include "agglo/electrostatics/solver.hpp"

namespace agglo::es {

inline constexpr std::string_view kIsolatedSolver = "isolated";

std::unique_ptr<Solver> make_isolated_spheres_solver(const SolverOptions& opt);

}  // namespace agglo::es
