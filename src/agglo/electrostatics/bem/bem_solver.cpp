#include "agglo/electrostatics/bem/bem_solver.hpp"

#include <stdexcept>

namespace agglo::es {

std::unique_ptr<Solver> make_bem_solver(const SolverOptions& /*opt*/) {
  throw std::runtime_error("bem: not implemented yet");
}

}  // namespace agglo::es
