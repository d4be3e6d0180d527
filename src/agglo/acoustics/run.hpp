#pragma once
// One acoustic run from a parsed config to its output files:
//   efficiency.csv  t, concentrations by phase [1/cm^3], fine efficiency, pure-droplet fraction,
//                   solid/liquid volume fractions (conservation), guard counters
//   psd.csv         dN/dlog10 d [1/cm^3] by phase at output.psd_times
//   snapshots.csv   samples with x <= snapshot_x_fraction * L_x at output.snapshot_times
//   summary.json    {"fine_efficiency": <final>, ...}
//   run.log         derived parameters, sampling, Nanbu guard statistics
// (config.resolved.toml, run.json and plots are written by the command.)
#include <string>

#include <nlohmann/json.hpp>

#include "agglo/acoustics/case_config.hpp"
#include "agglo/core/config.hpp"
#include "agglo/core/output.hpp"

namespace agglo::acoustics {

struct RunOptions {
  bool progress = true;
  std::string label = "acoustic";
};

// Parses cfg (ConfigError on bad input), runs, writes the files. Returns summary.json's content.
nlohmann::json run_acoustic(Config& cfg, const OutputDir& out, const RunOptions& opt = {});

// Start-up checks that need the sampled state (explicit stability, Nanbu bound). Throws ConfigError.
void check_startup(const AcousticCase& c, const Engine& e);

}  // namespace agglo::acoustics
