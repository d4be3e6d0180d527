#pragma once
// Spherical-harmonic (multipole) solver for spheres, MODEL B.2 item 3.
#include <memory>

#include "agglo/electrostatics/solver.hpp"

namespace agglo::es {
std::unique_ptr<Solver> make_spectral_solver(const SolverOptions& opt);
}  // namespace agglo::es
