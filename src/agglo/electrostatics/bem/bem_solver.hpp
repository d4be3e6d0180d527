#pragma once
// BEM: collocation boundary elements + GMRES (direct or FMM matvec), MODEL B.2 item 2.
#include <memory>

#include "agglo/electrostatics/solver.hpp"

namespace agglo::es {
std::unique_ptr<Solver> make_bem_solver(const SolverOptions& opt);
}  // namespace agglo::es
