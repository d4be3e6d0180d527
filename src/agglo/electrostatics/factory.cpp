#include "agglo/electrostatics/bem/bem_solver.hpp"
#include "agglo/electrostatics/coulomb_solver.hpp"
#include "agglo/electrostatics/solver.hpp"
#include "agglo/electrostatics/spectral/spectral_solver.hpp"

#include <stdexcept>

namespace agglo::es {

std::unique_ptr<Solver> make_solver(const SolverOptions& opt) {
  if (opt.solver == "coulomb") return make_coulomb_solver(opt);
  if (opt.solver == "spectral") return make_spectral_solver(opt);
  if (opt.solver == "bem") return make_bem_solver(opt);
  throw std::invalid_argument("unknown electrostatics solver '" + opt.solver + "' (coulomb, spectral, bem)");
}

}  // namespace agglo::es
