#pragma once
// The [electrostatics] section of a case file, and the electrostatic-radius helper (MODEL B.3).
//
//   [electrostatics]
//   solver              = "spectral"   # coulomb | spectral | bem
//   medium_permittivity = 1.0          # kappa_0 (> 0)
//   min_gap             = 0.01         # g_min: r_E = r / (1 + g_min/2)  (>= 0)
//   update_fraction     = 0.01         # re-solve when a particle moved this fraction of the
//                                      # smallest electrostatic gap since the last solve, (0, 1]
//   update_interval     = 0           # also re-solve at least every N steps (0 = off)
//   external_field      = [0, 0, 0]    # V/m
//   force_scale_chi     = false        # scale forces by chi^(2/5) (reduced-modulus users)
//   hold                = "constant"   # forces between solves: held (MODEL B.3), or "pair_corrected"
//   max_degree = 0, target_accuracy = 1e-4, max_degree_limit = 80          # spectral
//   patches_per_sphere = 2000, tolerance = 1e-6, max_iterations = 200,       # bem (tolerance and
//   matvec = "fmm", fmm_order = 0, fmm_leaf_size = 64                        #  iterations: all)
//
// Usage (DEM coupling):
//   EsConfig ec = parse_electrostatics(cfg.root());          // after cfg.root() is available
//   auto solver = es::make_solver(ec.options);
//   es::Problem p = make_problem(ec, centres, radii, charges, kappas);  // radii shrunk, checked
//   es::Solution s = solver->solve(p);
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/core/vec3.hpp"
#include "agglo/electrostatics/solver.hpp"

namespace agglo::es {

struct EsConfig {
  SolverOptions options;             // solver name and solver options
  double medium_permittivity = 1.0;  // kappa_0
  double min_gap = 0.01;             // g_min (dimensionless, relative to the radius)
  double update_fraction = 0.01;     // of the smallest electrostatic gap
  int update_interval = 0;           // steps; 0 = off
  Vec3 external_field;               // [V/m]
  bool force_scale_chi = false;
  std::string hold = "constant";  // between solves: "constant" (MODEL B.3) | "pair_corrected" (DEM coupling)
};

// Parse and range-check `section` (normally cfg.root().section("electrostatics")); defaults are
// written back into the table. Throws agglo::ConfigError with a one-line message.
EsConfig parse_electrostatics(const ConfigSection& section);

// Electrostatic radius r_E = r / (1 + g_min / 2) (MODEL B.3).
inline double electrostatic_radius(double r, double g_min) { return r / (1.0 + 0.5 * g_min); }

// Build the solver input: radii shrunk by g_min, charges and permittivities as given. Checks
// radius > 0, kappa_p > 0, finite values and that no two spheres overlap after shrinking
// (|x_i - x_j| > r_E,i + r_E,j); violations throw agglo::NumericalError naming the particles
// (use check_particles() to get ConfigError for input files instead).
Problem make_problem(const EsConfig& ec, const std::vector<Vec3>& centers, const std::vector<double>& radii,
                     const std::vector<double>& charges, const std::vector<double>& permittivities);

// Same checks, throwing agglo::ConfigError (bad input files): `what` names the source.
void check_particles(const Problem& p, const std::string& what);

// Smallest surface gap between electrostatic spheres [m] (infinity for < 2 spheres).
double smallest_gap(const Problem& p);

}  // namespace agglo::es
