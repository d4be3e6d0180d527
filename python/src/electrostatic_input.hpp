#pragma once
// Arguments of agglo.electrostatic_forces (electrostatic_forces.cpp) -> the solver input.
//
// Spheres: NumPy arrays in SI units (positions N x 3 [m], radii N [m], charges N [C], relative
// permittivities N; a scalar radius, charge or permittivity applies to every sphere), converted to
// float64 and checked (shape, real dtype, finite, radius and permittivity > 0). Solver name, medium
// permittivity, min_gap and the **options are range-checked by the [electrostatics] settings of the
// CLI (agglo/electrostatics/keys.hpp, parsed by es::parse_electrostatics), so a value is
// accepted here exactly when the case file would accept it. With min_gap the radii are shrunk to
// r_E = r / (1 + min_gap/2) (es::electrostatic_radius, docs/model.md §B.3), as in the DEM coupling and
// the CLI; without it the spheres are solved as given. Touching or overlapping spheres are refused.
// Sphere values outside the range of the [[particles]] key a case file would give them with
// (particles.position, radius, charge, permittivity) are refused as there. The solve's cost is checked
// against the budgets (max_steps, max_memory, else AGGLO_MAX_* or the defaults) as `agglo electrostatics`
// checks it: the lower bound from the sphere count before the O(N^2) check of the positions, then the
// estimate (es::static_solve_estimate; no output budget, nothing is written): agglo::run::LimitError.
// Every other failure throws agglo::ConfigError with one line "agglo.electrostatic_forces: ...".
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "agglo/electrostatics/solver.hpp"

namespace agglo::python {

struct EsArguments {
  pybind11::object positions, radii, charges, permittivities;  // array-likes
  pybind11::object solver, medium_permittivity, external_field, min_gap, threads;
  pybind11::object max_steps, max_memory;  // budgets (docs/limits.md): None, a number or a size text
  bool surface = false;                    // the surface samples are returned (counted in the memory)
  pybind11::kwargs options;  // solver options by [electrostatics] key name
};

struct EsInput {
  es::Problem problem;            // electrostatic radii (shrunk when min_gap is given)
  es::SolverOptions options;
  std::optional<double> min_gap;  // g_min when regularised
  std::optional<int> threads;     // OpenMP threads for the solve (0: all cores; none: the default)
};

// Validates and converts; throws agglo::ConfigError.
EsInput read_es_input(const EsArguments& a);

// Names of the accepted **options, as in the [electrostatics] table.
std::vector<std::string> es_option_names();

}  // namespace agglo::python
