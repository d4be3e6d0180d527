#pragma once
// Statistics over the members of an ensemble (runs of one case that differ only in their random seed).
// For the values x_1..x_n of one quantity in the n members:
//   mean  m = (1/n) sum_i x_i,   standard error of the mean  s = sqrt( sum_i (x_i - m)^2 / ((n - 1) n) )
// (sample variance with n - 1; s is NaN for n < 2). Sums run in member order, so the numbers do not
// depend on which thread or rank ran which member.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/io/dataset.hpp"

namespace agglo::io {

struct MeanStderr {
  double mean = 0.0;
  double standard_error = 0.0;  // of the mean
  std::size_t n = 0;
};
MeanStderr mean_stderr(const std::vector<double>& x);

// The part of a run's dataset that members can be averaged over: 0-d variables and variables whose every
// dimension has a coordinate variable (the 1-D variable named like the dimension, e.g. time, psd_time,
// diameter). Per-sample tables without one (the acoustic snapshot_row) are left out.
Dataset labelled_part(const Dataset& d);

// The ensemble of `members` (labelled parts of the members' datasets) as one dataset: each coordinate
// variable once (when it is the same, bitwise, in every member), and for every other variable that every
// member has on the same coordinates, "<name>_mean" and "<name>_stderr" (reals, units, long_name and
// attributes carried over, flag_* attributes dropped). Variables that cannot be averaged (absent in a
// member, or on a coordinate that differs between members) are named in the global attribute
// "not_averaged". std::invalid_argument when `members` is empty.
Dataset ensemble_dataset(const std::vector<Dataset>& members);

// One numeric summary scalar over the members (flattened name "a.b.c" as in sweep.csv, its unit from
// the name's suffix, io/dataset_scalars.hpp). Members where it is missing or not finite are left out
// (n counts the others), so a result read back from the journal (where JSON has no NaN) counts the same.
struct SummaryStat {
  std::string quantity;
  std::string unit;
  MeanStderr value;
};
std::vector<SummaryStat> summary_stats(const std::vector<nlohmann::json>& summaries);

}  // namespace agglo::io
