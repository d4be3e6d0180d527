#pragma once
// The [electrostatics] section and the [[particles]] entries of a case file, and the
// electrostatic-radius helper (docs/model.md §B.3). The keys, defaults and ranges are declared once in
// keys.hpp and agglo/core/settings_electrostatics.hpp (listed in docs/config.md).
//
// Usage (DEM coupling):
//   EsConfig ec = parse_electrostatics(cfg.root().section("electrostatics"));
//   auto solver = es::make_solver(ec.options);
//   es::Problem p = make_problem(ec, centres, radii, charges, kappas);  // radii shrunk, checked
//   es::Solution s = solver->solve(p);
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/core/settings_electrostatics.hpp"
#include "agglo/core/vec3.hpp"
#include "agglo/electrostatics/keys.hpp"
#include "agglo/electrostatics/solver.hpp"

namespace agglo::es {

// The declared [electrostatics] settings (defaults of EsConfig come from them).
inline const SolverKeys& es_keys() { return solver_keys(); }

struct EsConfig {
  SolverOptions options;  // solver name and solver options
  double medium_permittivity = es_keys().medium_permittivity.def();  // kappa_0
  double min_gap = es_keys().min_gap.def();  // g_min (dimensionless, relative to the radius)
  double update_fraction = es_keys().update_fraction.def();  // of the smallest electrostatic gap
  int update_interval = static_cast<int>(es_keys().update_interval.def());  // steps; 0 = off
  double force_tolerance = es_keys().force_tolerance.def();  // adaptive update_fraction; 0 = off
  Vec3 external_field;  // [V/m]
  bool force_scale_chi = es_keys().force_scale_chi.def();
  // Between solves: "constant" (docs/model.md §B.3) | "pair_corrected" | "extrapolated" (DEM coupling).
  std::string hold = std::string(es_keys().hold.def());
};

// One [[particles]] entry (electrostatics command; impact cases with agglomerate shape "list").
struct ParticleEntry {
  Vec3 position;            // [m]
  double radius = 0.0;      // [m]
  double charge = settings::electrostatics_settings().particles.charge.def();              // [C]
  double permittivity = settings::electrostatics_settings().particles.permittivity.def();  // kappa_p
};

// Reads one element of [[particles]] (ConfigSection from settings::...particles.t.elements(root)).
ParticleEntry parse_particle(const ConfigSection& element);

// The electrostatics command's case: [electrostatics] and at least one [[particles]] entry, radii
// shrunk to r_E; unknown keys rejected; overlapping spheres reported as a ConfigError.
struct EsCase {
  EsConfig settings;
  Problem problem;
  bool surface_output = settings::electrostatics_settings().output.surface.def();  // output.surface: surface.vtu
};
EsCase parse_electrostatics_case(Config& cfg);

// Parse and range-check `section` (normally cfg.root().section("electrostatics")); defaults are
// written back into the table. Throws agglo::ConfigError with a one-line message.
EsConfig parse_electrostatics(const ConfigSection& section);

// Electrostatic radius r_E = r / (1 + g_min / 2) (docs/model.md §B.3).
inline double electrostatic_radius(double r, double g_min) { return r / (1.0 + 0.5 * g_min); }

// Build the solver input: radii shrunk by g_min, charges and permittivities as given. Checks
// radius > 0, kappa_p > 0, finite values and that no two spheres overlap after shrinking
// (|x_i - x_j| > r_E,i + r_E,j); violations throw agglo::NumericalError naming the particles
// (use check_particles() to get ConfigError for input files instead).
Problem make_problem(const EsConfig& ec, const std::vector<Vec3>& centers, const std::vector<double>& radii,
                     const std::vector<double>& charges, const std::vector<double>& permittivities);
// The same into `p`, whose sphere array is reused (no allocation once it has the size: the DEM coupling).
void fill_problem(const EsConfig& ec, const std::vector<Vec3>& centers, const std::vector<double>& radii,
                  const std::vector<double>& charges, const std::vector<double>& permittivities, Problem& p);

// Same checks, the NumericalError mapped to agglo::ConfigError (bad input files): `what` names the source.
void check_particles(const Problem& p, const std::string& what);

// Smallest surface gap between electrostatic spheres [m] (infinity for < 2 spheres).
double smallest_gap(const Problem& p);

}  // namespace agglo::es
