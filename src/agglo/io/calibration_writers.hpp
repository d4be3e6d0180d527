#pragma once
// Files of `agglo calibrate` (docs/calibrate.md):
//   calibration.json          fitted values, their uncertainty and the feasible ranges, the targets with
//                             the surrogate's and the checked (achieved) observables and residuals
//                             and every [[prediction]]: its value at the best fit and its range over the
//                             feasible set's extreme points
//   calibration_points.csv    every mapped run: round, parameter values, per target the observable and
//                             its robustness weight in the surrogate (0 = rejected as off the trend)
//   calibration_surface.csv   the surrogate of every target over the whole parameter box (plots)
#include <nlohmann/json.hpp>

#include "agglo/calibrate/calibration.hpp"
#include "agglo/io/output_dir.hpp"

namespace agglo::io {

nlohmann::json calibration_json(const calibrate::Spec& spec, const calibrate::Result& r,
                                const std::vector<std::string>& case_files, const std::vector<std::string>& observables,
                                const std::vector<calibrate::Prediction>& predictions);
void write_calibration(const OutputDir& out, const calibrate::Spec& spec, const calibrate::Result& r,
                       const std::vector<std::string>& case_files, const std::vector<std::string>& observables,
                       const std::vector<calibrate::Prediction>& predictions);

}  // namespace agglo::io
