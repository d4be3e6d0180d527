#pragma once
// Electrostatic solvers by name. electrostatics.solver is looked up here and its allowed values are
// the registered names (keys.hpp), so a solver is declared once: its type (name, maker, cost model).
// The built-in types are listed in registry.cpp (coulomb_solver.hpp, spectral/spectral_solver.hpp,
// bem/bem_solver.hpp); a solver defined anywhere else registers with one line
//   const bool registered = agglo::es::register_solver({.name = "mine", .make = &make_my_solver});
// The cost model feeds the budgets and the --dry-run estimate (estimate.hpp, docs/limits.md); every
// part of it may be left out, which gives the cost of point charges.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "agglo/electrostatics/solver.hpp"

namespace agglo::es {

struct SolverType {
  std::string_view name;
  std::unique_ptr<Solver> (*make)(const SolverOptions&) = nullptr;
  // Bytes the solver holds for problem p besides the spheres and the output (default 0).
  double (*memory_bytes)(const SolverOptions&, const Problem&) = nullptr;
  // A lower bound of memory_bytes from the number of spheres alone, cheap enough to check before the
  // O(N^2) validation of the positions (default 0).
  double (*memory_lower_bound)(const SolverOptions&, double spheres) = nullptr;
  // Interaction evaluations of one solve with every GMRES iteration allowed (default N^2).
  double (*interactions)(const SolverOptions&, const Problem&) = nullptr;
  // Surface samples surface() returns per sphere (default 1, a point sample).
  double (*samples_per_sphere)(const SolverOptions&) = nullptr;
  // Wall seconds of one interaction on one thread, measured on the project's machine (the --dry-run
  // time estimate; default kPointChargeSeconds).
  double (*seconds_per_interaction)(const SolverOptions&) = nullptr;
  // Leaves of the [electrostatics] keys that drive the cost, most important first (named by --dry-run
  // and the budget errors before the sphere list).
  std::vector<std::string_view> cost_keys = {};
  // False for a solver of point charges: it induces no charges whatever the permittivities (the
  // impact cost estimate weighs such steps as plain DEM steps).
  bool induced_charges = true;
};

// Seconds of one point-charge interaction (the coulomb solver's, and the default).
inline constexpr double kPointChargeSeconds = 1.3e-9;

// Adds a type; throws std::logic_error if the name is taken or `make` is null. Returns true.
bool register_solver(SolverType type);

// The type named `name`; throws agglo::ConfigError naming the registered ones.
const SolverType& solver_type(std::string_view name);

// The registered names, built-ins first (the allowed values of electrostatics.solver).
std::vector<std::string> solver_names();

}  // namespace agglo::es
