#pragma once
// The [kernels] settings table, declared beside the mechanisms it names: the allowed values of
// kernels.model and kernels.brownian are the names the mechanisms of registry.hpp declare
// (`standalone`, `brownian_term`), so a mechanism appended to the registry is selectable from a case
// file with no further edit. Former spellings still read (docs/config.md): kernels.brownian = true/false
// ("brownian"/"none"), and the deprecated kernels.brownian_form ("fuchs" = kernels.brownian =
// "brownian_fuchs"), with a warning.
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/core/config.hpp"
#include "agglo/core/settings.hpp"
#include "agglo/core/settings_acoustic.hpp"

namespace agglo::acoustics {

struct KernelKeys {
  settings::Table t{"kernels", settings::kAcousticCommands, "collision kernels"};
  settings::Choice model{t, {"kernels.model", "", "kernel model: the acoustic sum, or one mechanism alone"},
                         kAcousticModel, &kernel_model_names};
  settings::Bool orthokinetic{t, {"kernels.orthokinetic", "", "orthokinetic (relative acoustic motion) collisions"},
                              true};
  settings::Bool acoustic_wake{t, {"kernels.acoustic_wake", "", "acoustic wake effect"}, true};
  settings::Bool radiation_pressure{t, {"kernels.radiation_pressure", "", "mutual radiation pressure"}, true};
  settings::Choice brownian;
  settings::Choice brownian_form{t,
                                 {"kernels.brownian_form", "",
                                  "deprecated: \"fuchs\" = kernels.brownian \"brownian_fuchs\"",
                                  "absent: read only when set"},
                                 std::nullopt, {"continuum_slip", "fuchs"}};
  settings::Bool inertia_correction{
      t, {"kernels.inertia_correction", "", "particle inertia correction of the motion"}, true};
  settings::Real collision_efficiency{t, {"kernels.collision_efficiency", "", "collision efficiency factor"}, 1.0,
                                      Range::closed(0.0, 1.0)};
  settings::Bool exclude_same_population{
      t, {"kernels.exclude_same_population", "", "no collisions within a population"}, false};
  settings::Real constant_coefficient{t, {"kernels.constant_coefficient", "m^3/s", "model constant: kernel value"},
                                      std::nullopt, Range::positive()};
  settings::Real additive_coefficient{t, {"kernels.additive_coefficient", "1/s", "model additive: kernel per volume"},
                                      std::nullopt, Range::positive()};

  KernelKeys();
};

// The table, listed by the settings catalogue after [domain].
const KernelKeys& kernel_keys();

// A case's [kernels] section (the inertia correction, a motion setting, is read by the caller).
KernelSettings read_kernels(const ConfigSection& s);

}  // namespace agglo::acoustics
