#pragma once
// Point charges, docs/model.md §B.2 item 1: exact when kappa_p = kappa_0 (a uniform shell has the exterior
// field of a point charge). In a medium kappa_0:
//   F_i = sum_k q_i q_k (x_i - x_k) / (4 pi eps0 kappa_0 |x_i - x_k|^3) + q_i E_ext,   torque 0,
//   U   = sum_i q_i^2 / (8 pi eps0 kappa_0 a_i) + sum_{i<k} q_i q_k / (4 pi eps0 kappa_0 |x_i - x_k|)
//         - 1/2 sum_i q_i E_ext . x_i      (= 1/2 \int phi sigma_f dS, self energy included).
// Surface samples: uniform sigma_f with sigma_b = sigma_f (1/kappa_0 - 1) (net charge q/kappa_0).
// Invalid input (validate_spheres.hpp) throws InvalidSpheres.
#include <memory>

#include "agglo/electrostatics/registry.hpp"

namespace agglo::es {
inline constexpr std::string_view kCoulombSolver = "coulomb";

std::unique_ptr<Solver> make_coulomb_solver(const SolverOptions& opt);

// The closed form above for a problem already checked (make_problem, fill_problem): forces and torques
// (zero) written into `force` and `torque`, resized to the spheres (no allocation once they have the
// size), the energy returned. The solver's solve() is this after validate_spheres(); the DEM coupling
// calls it directly for its κ_p = κ_0 fast path, once per solve.
double coulomb_forces(const Problem& p, std::vector<Vec3>& force, std::vector<Vec3>& torque);

// Its entry in the solver registry (registry.hpp), with its cost model.
SolverType coulomb_solver_type();
}  // namespace agglo::es
