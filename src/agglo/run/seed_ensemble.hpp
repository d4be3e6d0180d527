#pragma once
// Seed ensembles (`agglo acoustic CASE --seeds N`): N members of one case that differ only in their
// random seed, with the mean and standard error over the members of every time series, distribution and
// summary scalar (io/ensemble_stats.hpp). An ensemble is a sweep (run/sweep.hpp) over the command's seed
// key (Command::seed_key) with derived values: every member is one job of the ensemble runner, keyed by
// its index and journaled (--resume repeats only the missing members), and runs in its own folder
// case_<index>_<seed> (the sweep's naming) with the files of a single run. The statistics are made from
// the jobs' results alone ({"summary", "data"}, SweepPlan::keep_data), never from the member folders, so
// they are the same whichever thread or process ran a member.
//
// Member seeds depend on the base seed b (the case's seed) and the member index k only:
//   s_0 = b (member 0 is the single run of the case),
//   s_k = mix(mix(b) + k) & (2^63 - 1) for k >= 1 (the seed key's range is 0..2^63-1),
// where mix is the SplitMix64 finaliser (Steele, Lea & Flood 2014); a value equal to an earlier
// member's seed is mixed again until it is new.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "agglo/io/ensemble_stats.hpp"
#include "agglo/run/sweep.hpp"

namespace agglo::run {

std::vector<std::int64_t> member_seeds(std::int64_t base, std::size_t n);

// The plan of an n-member ensemble of `base`: plan_sweep over the seed key with member_seeds (every
// member validated), keep_data set, and a journal key of its own (a plain sweep's journal is not reused).
// ConfigError (one line naming --seeds, the value and what is allowed) when n < 1, or when `cmd` has no
// seed key.
SweepPlan plan_seed_ensemble(const Command& cmd, const Config& base, long long n);

// The cost of an ensemble: sweep_estimate plus its own files (mean and stderr: at most twice one
// member's output).
Estimate seed_ensemble_estimate(const Command& cmd, const SweepPlan& plan, const RunContext& ctx);

struct SeedEnsembleResult {
  SweepResult members;                    // cases (member folders), summaries and data by member index
  std::vector<std::int64_t> seeds;        // by member index
  std::vector<io::SummaryStat> summary;   // ensemble_summary.csv
  io::DatasetPtr data;                    // results.nc: io::ensemble_dataset + the member table
};

// The statistics of finished members from their job results (res.summaries, res.case_data);
// std::invalid_argument when a member has no data. results.nc's dataset: io::ensemble_dataset of the
// members, the sweep table of the members (dim `case`: their summary scalars) with member_seed (int64,
// exact), and the global attributes members (N) and seeds (int64 array).
SeedEnsembleResult ensemble_statistics(SweepResult res, const std::vector<std::int64_t>& seeds);

// The whole ensemble in the folder `path` (CLI, Python): cost checked against the budgets, then
// execute_sweep (member folders, journal.jsonl, sweep.csv, config.resolved.toml, run.json whose details
// name the command, members and seeds), then, in the output process only (run::is_output_rank),
// ensemble_summary.csv and ensemble_timeseries.csv (CSV format, io/ensemble_tables.hpp) and results.nc
// (NetCDF format; replaces the sweep's). Elsewhere the result holds the members only.
SeedEnsembleResult execute_seed_ensemble(const Command& cmd, const Config& base, SweepPlan& plan,
                                         const std::filesystem::path& path, const RunContext& ctx);

}  // namespace agglo::run
