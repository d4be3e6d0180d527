#pragma once
// The fractal law of an aggregate outcome table's structures (docs/outcomes.md "Fractal law of the
// structures"): N = k_f (R_g / a)^D_f with R_g the point-mass radius of gyration (structure/observables.hpp)
// and a the primary radius, recorded as the table's attributes for a DSMC population to take
// (population.fractal_law = "table", docs/acoustics.md §1.8).
//   requested: both partners are `fractal` with the same D_f and k_f: the builder's law, as requested;
//   fit:       otherwise (bpca, bcca, or two different laws): least squares of ln(R_g / a) against ln N
//              (structure::fit_fractal) over every structure the grid builds: both partners of every
//              tabulated pair of sizes and primary radii and every sample (the structures of the impacts,
//              rebuilt from their seeds: aggregate_outcome_case), at least three of at least two sizes;
//   none:      a fit without two sizes (one primary count and one radius).
#include <string>

#include "agglo/impact/outcome_grid.hpp"

namespace agglo::impact {

struct TableFractalLaw {
  bool known = false;
  double fractal_dimension = 0.0;  // D_f [1]
  double fractal_prefactor = 0.0;  // k_f [1]
  std::string how;                 // one line: "requested ..." or "fit ..." (the table's attribute)
};

// The law of the structures of the aggregate grid `s` over the case `base` (check_aggregate_pair done).
TableFractalLaw table_fractal_law(const ImpactCase& base, const OutcomeGridSpec& s);

}  // namespace agglo::impact
