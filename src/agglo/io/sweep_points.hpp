#pragma once
// The per-point statistics of a sweep with --seeds N (run/seed_ensemble.hpp): one row per point of the
// parameter grid, the mean and standard error over its N members (io/ensemble_stats.hpp) of every
// numeric summary scalar.
//   sweep_ensemble.csv: index, one column per swept key (the seed excluded), members, case (the folder of
//                       member 0, the point's run with the base seed), then <q>_mean,<q>_stderr for every
//                       summary scalar q of sweep.csv in first-seen order; 10 significant digits, "nan"
//                       for an undefined value (the s.e. of one member), empty when a point lacks q.
//   the dataset (sweep_ensemble.nc): dim point (coordinate `point`, the CSV's index), each numeric swept
//                       key as a variable named like the key (other keys as global attributes, JSON
//                       arrays as text), `members` (int), <q>_mean and <q>_stderr with the units of q.
#include <string>
#include <vector>

#include "agglo/io/dataset.hpp"
#include "agglo/io/ensemble_stats.hpp"
#include "agglo/io/output_dir.hpp"

namespace agglo::io {

struct SweepPoint {
  std::vector<std::string> values;  // one per swept key (the seed excluded)
  std::string folder;               // member 0's case folder
  std::size_t members = 0;
  std::vector<SummaryStat> stats;   // io::summary_stats of the members' summaries
};

void write_sweep_points(const OutputDir& out, const std::vector<std::string>& keys,
                        const std::vector<SweepPoint>& points);
Dataset sweep_points_dataset(const std::vector<std::string>& keys, const std::vector<SweepPoint>& points);

}  // namespace agglo::io
