#pragma once
// Parameter study: independent runs of any command over a grid of config values. Each case is the
// base case with `key=value` applied for every axis (Config::apply_override), validated before anything
// runs, run in its own folder case_<index>_<values> by run::execute, and its summary becomes one row of
// sweep.csv. Cases are jobs of the ensemble runner (threads shared, results in grid order whatever the
// scheduling, journaled so that `--resume` repeats only the missing cases).
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/io/dataset.hpp"
#include "agglo/run/command.hpp"

namespace agglo::run {

struct SweepAxis {
  std::string key;                  // dotted config key, e.g. population.1.diameter
  std::vector<std::string> values;  // TOML values as given
};

struct SweepCase {
  std::size_t index = 0;
  std::vector<std::string> values;       // one per axis
  std::vector<std::string> assignments;  // "key=value" per axis
  std::string folder;                    // case_<index>_<values>
};

// "v1,v2,..." -> values (whitespace trimmed; empty entries rejected with ConfigError).
std::vector<std::string> split_values(const std::string& list);

// The grid (last axis fastest); ConfigError on an empty key or no values.
std::vector<SweepCase> sweep_grid(const std::vector<SweepAxis>& axes);

struct SweepResult {
  std::vector<SweepCase> cases;
  std::vector<nlohmann::json> summaries;  // by case index
  std::vector<nlohmann::json> case_data;  // by case index, with SweepPlan::keep_data only: each case's data
                                          // (io::labelled_part as io/dataset_json.hpp; null if none)
  io::DatasetPtr data;                    // the sweep table as labelled arrays (results.nc, Python)
};

// The folder of run `index` of a grid: <prefix>_<index, 2 digits>_<values joined by "_", characters
// other than letters, digits, ".", "-", "+" as "_"> (e.g. case_03_2e-05_17).
std::string grid_folder(std::string_view prefix, std::size_t index, const std::vector<std::string>& values);

// The validated cases of a sweep: every case is the base case with its assignments applied, parsed once by
// `cmd` (run::plan: defaults written in, ConfigError naming the first bad case) and estimated, before any
// folder or file is made. The runs use these parsed configs and estimates (execute_planned).
struct SweepPlan {
  std::vector<SweepCase> cases;
  std::vector<Config> configs;       // by case index, parsed
  std::vector<Estimate> estimates;   // by case index: run::plan of one case on one thread
  std::string journal_key;           // identifies the base case and command in journal.jsonl
  std::filesystem::path cases_root;  // folder of the case folders (empty: run_sweep's `out`)
  // Seed ensembles (run/seed_ensemble.hpp): each case's job returns {"summary": ..., "data": ...} (its
  // dataset's io::labelled_part as JSON) instead of the summary alone, so the ensemble statistics come
  // from the job results (journal, MPI messages) and never from the case folders.
  bool keep_data = false;
};
SweepPlan plan_sweep(const Command& cmd, const Config& base, const std::vector<SweepAxis>& axes,
                     const RunContext& ctx = {});

// The cost of a whole sweep: steps and output summed over its cases; memory of the cases that run at
// the same time (the largest min(threads, cases) case estimates) plus run::kProcessBaseBytes once.
Estimate sweep_estimate(const SweepPlan& plan, const RunContext& ctx);

// Runs `cmd` for every case of the plan under `out` (the whole ensemble: run/ensemble_request.hpp). Throws
// the first failure (in case order) after every case has run.
SweepResult run_sweep(const Command& cmd, SweepPlan& plan, const OutputDir& out, const RunContext& ctx);

}  // namespace agglo::run
