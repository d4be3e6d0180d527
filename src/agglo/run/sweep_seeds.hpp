#pragma once
// Parameter sweeps with error bars (`agglo sweep ... --seeds N`, agglo.sweep(..., seeds=N)): every point of
// the grid runs with the same N member seeds, member_seeds of the base case's seed (run/seed_ensemble.hpp),
// so member 0 of each point is the case of the plain sweep, and the points share their random numbers
// (differences between points are less noisy than with independent seeds). The seed is the grid's last,
// fastest axis: sweep.csv keeps one row per run, and the journal, --resume and the MPI farm work as for
// any sweep. Per point, the mean and standard error over its members of every summary scalar
// (io/ensemble_stats.hpp) go to sweep_ensemble.csv and sweep_ensemble.nc (io/sweep_points.hpp).
#include <filesystem>
#include <vector>

#include "agglo/io/sweep_points.hpp"
#include "agglo/run/sweep.hpp"

namespace agglo::run {

// `axes` with the seed axis of n members appended. ConfigError (one line naming --seeds, the value and
// what is allowed) when n < 2, when `cmd` has no random seed, or when an axis already varies the seed.
std::vector<SweepAxis> with_seed_axis(const Command& cmd, const Config& base, std::vector<SweepAxis> axes,
                                      long long n);

// The points of a finished sweep whose last axis is the seed axis of `members` members: the cases come
// in grid order, so point p holds cases p*members .. p*members + members - 1.
std::vector<io::SweepPoint> sweep_points(const SweepResult& res, std::size_t members);

struct SeededSweep {
  SweepResult runs;                    // every run (point x member); runs.data is the runs' table
  std::vector<io::SweepPoint> points;  // empty outside the output process (run::is_output_rank)
};

// execute_sweep over `axes` (the seed axis included, as with_seed_axis made them), then, in the output
// process, sweep_ensemble.csv (CSV format) and sweep_ensemble.nc (NetCDF format).
SeededSweep execute_seeded_sweep(const Command& cmd, const Config& base, const std::vector<SweepAxis>& axes,
                                 SweepPlan& plan, const std::filesystem::path& path, const RunContext& ctx,
                                 const nlohmann::json& details);

}  // namespace agglo::run
