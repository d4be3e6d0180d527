#pragma once
// Parsing and validation of an acoustic case file (sections [gas], [sound], [domain], [time],
// [[population]], [kernels], [outcomes], [output], key `seed`). Every default is written back
// into the config so that Config::resolved_toml() is the complete case. See docs/acoustics.md.
#include <vector>

#include "agglo/acoustics/engine.hpp"
#include "agglo/core/config.hpp"

namespace agglo::acoustics {

struct OutputSettings {
  std::vector<double> psd_times;       // [s]
  int psd_bins = 60;
  double psd_d_min = 1e-8, psd_d_max = 1e-4;  // [m]
  double efficiency_interval = 0.01;   // [s]
  std::vector<double> snapshot_times;  // [s]
  double snapshot_x_fraction = 0.25;   // snapshots keep 0 <= x <= fraction * length_x
  bool plots = true;
};

struct AcousticCase {
  EngineSettings engine;
  OutputSettings output;
  std::string file;
};

// Throws ConfigError (one line naming file, key, value and rule) on any problem.
AcousticCase parse_acoustic_case(Config& cfg);

}  // namespace agglo::acoustics
