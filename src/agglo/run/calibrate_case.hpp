#pragma once
// A calibration file ([calibrate], [[parameter]], [[target]]; settings_calibrate.hpp) parsed and
// validated: the fit's Spec, and per target its case (loaded relative to the calibration file, every
// parameter key checked against it at both ends of its range) and observable.
#include <filesystem>
#include <string>
#include <vector>

#include "agglo/calibrate/calibration.hpp"
#include "agglo/core/config.hpp"

namespace agglo::run {

struct CalibrationTarget {
  std::filesystem::path file;
  std::string observable;  // "v_crit" | "v50"
  Config base;             // the target case as loaded (overrides are applied to clones)
  std::string resolved;    // its resolved TOML (hashed into the journal keys of its runs)
};

struct CalibrateCase {
  calibrate::Spec spec;
  std::vector<CalibrationTarget> targets;
  std::vector<CalibrationTarget> predictions;  // [[prediction]] cases
  std::string predict;                         // calibrate.predict: "none" | "best" | "range"
};

// ConfigError (one line naming the key) for a bad fit setting, an empty range, a missing case file or
// a parameter key that a target case does not accept.
CalibrateCase parse_calibrate_case(Config& cfg);

// The case of a target (or prediction) with the parameters set to x, parsed as an impact case would be
// (ConfigError otherwise).
Config target_config(const CalibrateCase& c, const CalibrationTarget& t, const std::vector<double>& x);

}  // namespace agglo::run
