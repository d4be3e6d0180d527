#pragma once
// One request for every ensemble of runs of a command: `agglo sweep` (a grid of config values, with or
// without --seeds), `agglo <command> --seeds N` (a seeded ensemble with no axes: the case alone), agglo.sweep
// and agglo.<command>(seeds=N) in Python; under mpirun the runs are spread over the ranks by the task farm
// behind run_jobs (run/ensemble.hpp). The front ends only turn their arguments into an EnsembleRequest and a
// RunContext; planning, the refusals, run.json's details, the files and the statistics are made here.
//
// plan_ensemble validates everything before a folder is made: each case (the base with one grid point's
// assignments, run/sweep.hpp) is parsed once and estimated, the whole cost is known (--dry-run), and the
// request's refusals are one-line ConfigErrors naming --seeds, --param or --checkpoint. execute_ensemble then
// claims the folder, runs the cases (journal.jsonl: --resume repeats only the missing runs), and writes in
// the output process (run::is_output_rank):
//   every ensemble:  case_<i>_<values>/ (each run's own files), sweep.csv (one row per run), results.nc (the
//                    runs' table), config.resolved.toml, run.json;
//   with seeds >= 2: per point (run/seed_ensemble.hpp) ensemble_summary.csv, ensemble_timeseries.csv and
//                    results.nc (mean and s.e. of every summary scalar, time series and size distribution,
//                    io/ensemble_tables.hpp) — in the folder itself when nothing is swept (results.nc then
//                    holds the statistics instead of the runs' table), else in point_<p>_<values>/, and
//                    sweep_ensemble.csv / sweep_ensemble.nc with every point's scalar statistics
//                    (io/sweep_points.hpp).
// run.json records the command `sweep`, or the command itself for a seed ensemble without axes (so that
// `acoustic --seeds N --resume` continues its folder), with the details of ensemble_details.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/io/sweep_points.hpp"
#include "agglo/run/sweep.hpp"

namespace agglo::run {

struct EnsembleRequest {
  std::string command = "acoustic";  // the command of every run (run::find_command)
  Config base;                       // the case with the front end's overrides applied (not parsed)
  std::vector<SweepAxis> axes;       // the grid (last axis fastest); empty: the case alone (seeds >= 2)
  long long seeds = 1;               // members per point; >= 2 adds the seed axis (run/seed_ensemble.hpp)
  std::filesystem::path folder;      // the output folder
};

// The run.json details of an ensemble: {"command", "param", "values"} for the axes (a key and its list of
// values for one axis, the keys and their comma-joined lists for several; absent without axes), and with
// seeds >= 2 {"ensemble": "seeds", "members": N, "seeds": [member seeds]}.
nlohmann::json ensemble_details(const std::string& command, const std::vector<SweepAxis>& axes,
                                const std::vector<std::int64_t>& member_seeds);

struct EnsemblePlan {
  const Command* cmd = nullptr;
  EnsembleRequest request;
  std::vector<SweepAxis> axes;            // the grid run: request.axes, then the seed axis (seeds >= 2)
  std::vector<std::int64_t> seeds;        // member seeds (seeds >= 2), the same at every point
  SweepPlan sweep;                        // the cases, parsed once, and their estimates
  Config resolved;                        // config.resolved.toml of the ensemble folder
  long long seed = 0;                     // run.json's seed: the base case's (the first case's if invalid alone)
  std::string recorded;                   // run.json's command: "sweep", or the command (seeds without axes)
  nlohmann::json details;                 // ensemble_details
  Estimate estimate;                      // every run plus the statistics files
  std::size_t members() const { return seeds.empty() ? 1 : seeds.size(); }
  // A seed ensemble of the case alone: its one point's statistics are the folder's own files.
  bool one_point() const { return !seeds.empty() && request.axes.empty(); }
};

// Everything checked before anything is made. ConfigError (one line) for an unknown command, an empty
// grid without seeds, --seeds < 1, --seeds >= 2 for a command without a seed or with the seed swept,
// --checkpoint (ctx.checkpoint_interval > 0) with an ensemble, or a bad case.
EnsemblePlan plan_ensemble(EnsembleRequest request, const RunContext& ctx);

struct EnsembleResult {
  SweepResult runs;                       // every run (point x member) in grid order; runs.data: their table
  std::vector<io::SweepPoint> points;     // seeds >= 2, output process: each point's scalar statistics
  std::vector<std::string> point_folders; // by point: its statistics folder ("" = the ensemble's own)
  io::DatasetPtr data;                    // results.nc of the folder: the statistics (seeds without axes),
                                          // else the runs' table
};

// The plan's cost checked against the budgets, then the runs, files and statistics above. After a
// failure run.json says "incomplete" (interrupted) or "failed" and the error is rethrown.
EnsembleResult execute_ensemble(EnsemblePlan& plan, const RunContext& ctx);
// plan_ensemble + execute_ensemble.
EnsembleResult execute_ensemble(EnsembleRequest request, const RunContext& ctx);

}  // namespace agglo::run
