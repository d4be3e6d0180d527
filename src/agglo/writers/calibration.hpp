#pragma once
// Files of `agglo calibrate` (docs/calibrate.md):
//   calibration.json          fitted values, their uncertainty and the feasible ranges, the targets with
//                             the surrogate's and the checked (achieved) observables and residuals
//                             and every [[prediction]]: its value at the best fit and its range over the
//                             feasible set's extreme points
//   calibration_points.csv    every mapped run: round, parameter values, per target the observable and
//                             its robustness weight in the surrogate (0 = rejected as off the trend)
//   calibration_surface.csv   the surrogate of every target over the whole parameter box (plots)
//   results.nc                the two tables (points_table: dim point, x{j} with the unit of its config
//                             key and attribute config_key; surface_table: dim surface_point, the CSV's
//                             x{j} as surface_x{j}); dim parameter: best (the fitted values), feasible_lo,
//                             feasible_hi; calibration.json's numeric and boolean scalars as 0-d variables
//                             (nested objects "<a>_<b>").
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/calibrate/calibration.hpp"
#include "agglo/io/dataset.hpp"
#include "agglo/io/output_dir.hpp"
#include "agglo/io/table.hpp"

namespace agglo::writers {

// calibration_points.csv (dim point): round, x0..x{d-1} (parameter values), then per target k obs{k}
// (its observable, NaN: none) and weight{k} (robustness weight in the surrogate).
io::Table points_table(const calibrate::Spec& spec, const calibrate::Result& r);
// calibration_surface.csv (dim surface_point): x0..x{d-1}, surrogate{k} per target.
io::Table surface_table(const calibrate::Spec& spec, const calibrate::Result& r);

nlohmann::json calibration_json(const calibrate::Spec& spec, const calibrate::Result& r,
                                const std::vector<std::string>& case_files, const std::vector<std::string>& observables,
                                const std::vector<calibrate::Prediction>& predictions);
void write_calibration(const OutputDir& out, const calibrate::Spec& spec, const calibrate::Result& r,
                       const std::vector<std::string>& case_files, const std::vector<std::string>& observables,
                       const std::vector<calibrate::Prediction>& predictions);

io::Dataset calibration_dataset(const calibrate::Spec& spec, const calibrate::Result& r,
                                const std::vector<std::string>& case_files,
                                const std::vector<std::string>& observables,
                                const std::vector<calibrate::Prediction>& predictions);

}  // namespace agglo::writers
