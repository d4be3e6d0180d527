#pragma once
// A sectional case: the acoustic case file (acoustics/case_config.hpp) plus its [sectional] section
// (keys declared in core/settings_acoustic.hpp, docs/config.md). The sectional solver takes one
// component that always coalesces, with a kernel of the sizes only; anything else is a ConfigError
// naming the key: kernels.model must be constant, additive, brownian_fuchs or brownian_partmc,
// outcomes.always_coalesce true, kernels.exclude_same_population false, and every [[population]] the
// same phase and density, and compact (population.structure = "fractal" is refused).
#include "agglo/acoustics/case_config.hpp"
#include "agglo/core/config.hpp"

namespace agglo::sectional {

struct SectionalSettings {
  int bins_per_decade = 40;  // pivots per decade of diameter
  double d_min = 1e-9;       // smallest pivot diameter [m]
  double d_max = 1e-3;       // largest pivot diameter [m] (the last pivot is at or just above it)
  double tolerance = 1e-6;   // local error per time step relative to N and to the volume
};

struct SectionalCase {
  acoustics::AcousticCase base;
  SectionalSettings grid;
};

SectionalCase parse_sectional_case(Config& cfg);

}  // namespace agglo::sectional
