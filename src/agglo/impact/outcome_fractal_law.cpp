#include "agglo/impact/outcome_fractal_law.hpp"

#include <fmt/format.h>

#include "agglo/impact/outcome_aggregates.hpp"
#include "agglo/structure/observables.hpp"

namespace agglo::impact {

TableFractalLaw table_fractal_law(const ImpactCase& base, const OutcomeGridSpec& s) {
  TableFractalLaw law;
  const AgglomerateSpec &t = base.agglomerate, &p = base.projectile.body;
  if (base.agglomerate.shape == "fractal" && base.projectile.shape == "fractal" &&
      t.fractal_dimension == p.fractal_dimension && t.fractal_prefactor == p.fractal_prefactor) {
    law = {true, t.fractal_dimension, t.fractal_prefactor,
           "requested: both partners built by the fractal builder with this D_f and k_f"};
    return law;
  }
  std::vector<double> n, rg_over_a;
  for (const OutcomeImpact& j : outcome_impacts(s)) {
    if (j.iv != 0 || j.c1 != 0 || j.c2 != 0 || j.ik != 0) continue;  // the structures of one speed and charge
    const ImpactCase c = aggregate_outcome_case(base, s, j);
    for (const AgglomerateSpec* a : {&c.agglomerate, &c.projectile.body}) {
      n.push_back(static_cast<double>(a->structure.size()));
      rg_over_a.push_back(structure::rg_point_mass(a->structure) / a->radius);
    }
  }
  bool sizes = false;
  for (double x : n) sizes = sizes || x != n.front();
  if (n.size() < 3 || !sizes) return law;
  const structure::FractalFit f = structure::fit_fractal(n, rg_over_a);
  law = {true, f.fractal_dimension, f.fractal_prefactor,
         fmt::format("fit of ln(R_g/a) against ln N over the {} {}/{} structures the grid builds (D_f standard "
                     "error {:.3g})",
                     f.points, base.agglomerate.shape, base.projectile.shape, f.dimension_stderr)};
  return law;
}

}  // namespace agglo::impact
