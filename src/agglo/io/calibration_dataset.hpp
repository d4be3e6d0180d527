#pragma once
// results.nc of `agglo calibrate` (io/dataset.hpp), the content of its CSV files and calibration.json:
//   dim point (calibration_points.csv's rows): round, x0..x{d-1} (parameter values, attribute config_key),
//     obs{k}, weight{k} per target k;
//   dim surface_point (calibration_surface.csv's rows): surface_x0.., surrogate{k};
//   dim parameter: best (the fitted values), feasible_lo, feasible_hi;
//   calibration.json's numeric and boolean scalars as 0-d variables (nested objects "<a>_<b>").
#include <string>
#include <vector>

#include "agglo/calibrate/calibration.hpp"
#include "agglo/io/dataset.hpp"

namespace agglo::io {

Dataset calibration_dataset(const calibrate::Spec& spec, const calibrate::Result& r,
                            const std::vector<std::string>& case_files, const std::vector<std::string>& observables,
                            const std::vector<calibrate::Prediction>& predictions);

}  // namespace agglo::io
