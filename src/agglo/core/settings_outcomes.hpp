#pragma once
// Settings table of agglo outcomes (impact/outcome_grid.hpp, docs/outcomes.md): the grid of the
// sphere-sphere or aggregate-aggregate outcome table (primaries instead of diameters:
// impact/outcome_aggregates.hpp). The DEM case itself is read through the impact tables (settings_impact.hpp).
#include <cstdint>
#include <vector>

#include "agglo/core/settings.hpp"

namespace agglo::settings {

struct OutcomesSettings {
  struct Grid {
    Table t{"outcome_grid", "outcomes", "grid of the sphere-sphere or aggregate-aggregate outcome table (agglo outcomes)"};
    Reals speeds{t, {"outcome_grid.speeds", "m/s", "normal relative speeds at contact (increasing)"}, std::nullopt,
                 Range::open_closed(0.0, 1e3)};
    Reals diameters{t, {"outcome_grid.diameters", "m", "sphere diameters of both partners (increasing; or primaries)"},
                    std::nullopt, Range::open_closed(0.0, 1e-2)};
    Reals primaries{t, {"outcome_grid.primaries", "", "primary counts of both aggregate partners (increasing; "
                                                       "instead of diameters)"},
                    std::nullopt, Range::closed(2.0, 1e5)};
    // Read only when set (tables without them resolve as before).
    Reals charges{t,
                  {"outcome_grid.charges", "C/m^2",
                   "surface charge densities sigma of each partner (signed, increasing): charge sigma pi d^2, d the "
                   "(volume-equivalent) diameter",
                   "the case's charges (no charge axes)"},
                  std::nullopt, Range::closed(-1e-2, 1e-2)};
    Reals permittivities{t,
                         {"outcome_grid.permittivities", "",
                          "relative permittivities kappa_p of both partners (increasing)",
                          "the case's permittivities (no permittivity axis)"},
                         std::nullopt, Range::open_closed(0.0, 1e6)};
    Reals primary_radii{t,
                        {"outcome_grid.primary_radii", "m",
                         "primary radii a of the aggregate partners (increasing; with primaries: the counts at the first "
                         "radius, each partner's radius from this axis)",
                         "agglomerate.radius (one primary radius, no primary-radius axes)"},
                        std::nullopt, Range::open_closed(0.0, 1e-2)};
    Integer impacts{t, {"outcome_grid.impacts", "", "impacts per grid node (sampled impact parameters)"}, 8, 1,
                    100000};
    Real max_offset{t, {"outcome_grid.max_offset", "", "largest impact parameter b / (r_1 + r_2); 0 = every impact head-on"},
                    0.5, Range::closed(0.0, 0.95)};
    Integer seed{t, {"outcome_grid.seed", "", "random seed of the sampled impact parameters"}, 1, 0, INT64_MAX};
  } grid;

  std::vector<const Table*> tables() const { return {&grid.t}; }
};

const OutcomesSettings& outcomes_settings();

}  // namespace agglo::settings
