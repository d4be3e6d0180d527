#pragma once
// Point charges (exact for kappa_p = kappa_0), MODEL B.2 item 1.
#include <memory>

#include "agglo/electrostatics/solver.hpp"

namespace agglo::es {
std::unique_ptr<Solver> make_coulomb_solver(const SolverOptions& opt);
}  // namespace agglo::es
