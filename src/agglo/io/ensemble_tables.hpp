#pragma once
// The CSV tables of a seed ensemble (run/seed_ensemble.hpp), statistics as in io/ensemble_stats.hpp:
//   ensemble_summary.csv:    quantity,unit,mean,stderr,n — one row per numeric summary scalar
//                            (flattened names as in sweep.csv);
//   ensemble_timeseries.csv: t_s, then <name>_mean,<name>_stderr for every variable of the ensemble
//                            dataset on the dimension `time` alone (nothing when it has no time).
// Numbers with 10 significant digits; an undefined value (stderr of one member) is "nan".
#include <vector>

#include "agglo/io/dataset.hpp"
#include "agglo/io/ensemble_stats.hpp"
#include "agglo/io/output_dir.hpp"

namespace agglo::io {

void write_ensemble_summary(const OutputDir& out, const std::vector<SummaryStat>& stats);
void write_ensemble_timeseries(const OutputDir& out, const Dataset& ensemble);

}  // namespace agglo::io
