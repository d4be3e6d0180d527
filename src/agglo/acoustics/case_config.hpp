#pragma once
// Parsing and validation of an acoustic case file (sections [gas], [sound], [domain], [time],
// [[population]], [sampling], [kernels], [outcomes], [output], key `seed`). Every default is written back
// into the config so that Config::resolved_toml() is the complete case. See docs/acoustics.md;
// the keys, defaults and ranges are declared in agglo/core/settings_acoustic.hpp (docs/config.md).
#include <vector>

#include "agglo/acoustics/engine.hpp"
#include "agglo/core/config.hpp"
#include "agglo/core/settings_acoustic.hpp"

namespace agglo::acoustics {

// Defaults are the declared [output] settings (agglo/core/settings_acoustic.hpp); the times
// depend on the run end and are filled in by the parser.
struct OutputSettings {
  std::vector<double> psd_times;  // [s]
  int psd_bins = static_cast<int>(settings::acoustic_settings().output.psd_bins.def());
  double psd_d_min = settings::acoustic_settings().output.psd_d_min.def();  // [m]
  double psd_d_max = settings::acoustic_settings().output.psd_d_max.def();  // [m]
  double efficiency_interval = 0.0;    // [s]; default: run end / 200
  std::vector<double> snapshot_times;  // [s]
  double snapshot_x_fraction = settings::acoustic_settings().output.snapshot_x_fraction.def();  // keep x <= f L_x
  bool plots = settings::acoustic_settings().output.plots.def();
};

struct AcousticCase {
  EngineSettings engine;
  OutputSettings output;
  std::string file;
};

// Throws ConfigError (one line naming file, key, value and rule) on any problem.
AcousticCase parse_acoustic_case(Config& cfg);

}  // namespace agglo::acoustics
