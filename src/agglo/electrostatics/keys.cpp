#include "agglo/electrostatics/keys.hpp"

#include "agglo/core/settings_catalogue.hpp"
#include "agglo/core/settings_impact.hpp"

namespace agglo::es {

const SolverKeys& solver_keys() {
  static const SolverKeys k;
  static const bool listed = settings::add_table(k.t, settings::impact_settings().wall.t);
  (void)listed;
  return k;
}

}  // namespace agglo::es
