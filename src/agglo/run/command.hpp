#pragma once
// The run pipeline shared by every front end (CLI, Python, MPI): a command turns a case into results
// in four steps — parse (TOML -> validated settings; ConfigError on bad input), run (the engine,
// which never prints or writes files), summarise (observations -> a JSON summary), write (the
// writers in io/). `execute` adds what every output folder gets: config.resolved.toml (the case
// with every default filled in) and run.json (version, git hash, command, seed, threads, wall time).
// Commands are looked up by name, so `sweep` (and later calibrate, MPI) runs any of them.
// Before the output folder is created, `execute` compares the command's Estimate (steps, memory,
// output) with the budgets (run/budget.hpp) and refuses a case that exceeds one (docs/limits.md).
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/core/config.hpp"
#include "agglo/core/estimate.hpp"
#include "agglo/core/settings.hpp"
#include "agglo/io/dataset.hpp"
#include "agglo/io/netcdf_writer.hpp"
#include "agglo/io/output_dir.hpp"
#include "agglo/run/budget.hpp"
#include "agglo/run/reporter.hpp"

namespace agglo::run {

// Which result files a run writes besides config.resolved.toml and run.json (--format).
struct OutputFormats {
  bool csv = true;      // the CSV/JSON files of each command (and VTK snapshots, plots)
  bool netcdf = true;   // results.nc (io/netcdf_writer.hpp)
};

// The bytes a run writes in the formats `f`, from a command's output estimate (its CSV/JSON/VTK files):
// results.nc holds the same numbers in at most as many bytes (8 per value against 10-17 characters) plus
// kNetcdfOverhead for its metadata (HDF5 headers and attributes, about 1 KiB per variable; measured
// 30 KiB for the 60 variables of an acoustic run). With NetCDF the memory estimate grows by the CSV
// estimate too (the dataset's arrays, held until results.nc is written).
inline constexpr double kNetcdfOverhead = 64.0 * 1024.0;
double output_bytes(double csv_estimate, const OutputFormats& f);

// The formats named by `text`: "csv", "netcdf" or "csv,netcdf" (either order) — the one parser of the CLI's
// --format and Python's format=. ConfigError naming the text and what is allowed otherwise.
OutputFormats parse_formats(std::string_view text);

struct RunContext {
  Reporter* reporter = nullptr;          // null = silent
  const CancelToken* cancel = nullptr;   // null = not cancellable
  int threads = 0;                       // 0 = all cores
  bool resume = false;                   // reuse the journal of finished jobs in the output folder
  bool overwrite = false;                // clear an output folder holding an earlier run
  const Budgets* budgets = nullptr;      // null = resolve_budgets({}): environment, then defaults
  double checkpoint_interval = 0.0;      // simulated seconds between checkpoints (0 = none; --checkpoint)
  OutputFormats formats;                 // --format
  Reporter& report() const;
  int thread_count() const;              // threads, or all cores when 0
};

struct CommandResult {
  nlohmann::json summary;                // scalars of the run (sweep tables, Python)
  nlohmann::json details;                // extra block of run.json (null = none)
  long long seed = 0;                    // recorded in run.json
  std::string plot_script;               // scripts/<name> making the PNGs ("" = none)
  std::vector<std::string> plot_args;
  io::DatasetPtr data;                   // the results as labelled arrays (results.nc, Python); may be null
};

// A command-line shortcut for one config key, e.g. `collide --speed V` for projectile.speed.
struct Shortcut {
  std::string flags;               // CLI11 flag names, e.g. "-v,--speed"
  const settings::Setting* key;    // the key it overrides
};

class Command {
 public:
  virtual ~Command() = default;
  virtual std::string_view name() const = 0;
  virtual std::string_view help() const = 0;
  // Parses and validates the whole case, unknown keys included; writes defaults into cfg.
  virtual void parse(Config& cfg) const = 0;
  // Command-line shortcuts for config keys (none by default).
  virtual std::vector<Shortcut> shortcuts() const { return {}; }
  // What a parsed case (cfg has passed parse()) will cost, from the case alone (no large allocation);
  // an ensemble's estimate covers all its runs, `ctx.threads` of them at a time. None by default.
  virtual Estimate estimate(Config& cfg, const RunContext& ctx) const;
  // A lower bound of estimate() from the sizes in the case alone, checked before parse() so that a
  // huge case is refused before a slow (e.g. O(N^2)) validation. None by default.
  virtual Estimate lower_bound(Config& cfg) const;
  // Seconds of one thread per unit of the step estimate, measured on the development machine
  // (docs/limits.md, "Time estimate"); --dry-run multiplies the steps by it. 0: not calibrated.
  virtual double seconds_per_step(Config& cfg) const;
  // The random seed a case runs with (recorded in run.json); 0 for deterministic commands.
  virtual long long seed(const Config& cfg) const;
  // The config key of the random seed, for seed ensembles (run/seed_ensemble.hpp, `--seeds N`); null for
  // deterministic commands.
  virtual const settings::Setting* seed_key() const { return nullptr; }
  // True for ensembles that continue from their journal under --resume; a single run restarts instead.
  virtual bool resumable() const { return false; }
  // True for single runs that write checkpoints (--checkpoint) and continue from the last one under
  // --resume (the folder is kept; run() reads out.file(kCheckpointFile) when ctx.resume is set).
  virtual bool restartable() const { return false; }
  // Runs a parsed case and writes the command's own files into `out`.
  virtual CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const = 0;
};

// The command called `name`; ConfigError naming the available ones otherwise.
const Command& find_command(std::string_view name);
std::vector<std::string> command_names();

// Resident memory of the process before a command allocates anything (program, libraries, OpenMP
// runtime), added to every memory estimate.
inline constexpr double kProcessBaseBytes = 16.0 * 1024.0 * 1024.0;

// cmd.parse(cfg), the only way the run layer parses a case (plan, plan_sweep, a sweep's base), so that a
// case is parsed once per run: an ensemble parses each of its cases once when it is planned and runs it
// with execute_planned. case_parses() counts the calls (all threads), for the tests that check it.
void parse_case(const Command& cmd, Config& cfg);
std::size_t case_parses();

// lower bound within the budgets (ConfigError otherwise) -> parse -> estimate (cmd.estimate plus
// kProcessBaseBytes; output in ctx.formats, and memory plus the results.nc arrays with NetCDF); cfg gets
// its defaults written in.
Estimate plan(const Command& cmd, Config& cfg, const RunContext& ctx);
// The budgets of a context (ctx.budgets, else resolve_budgets({})).
Budgets budgets_of(const RunContext& ctx);

// parse -> estimate within the budgets -> output folder -> run -> config.resolved.toml + run.json. `extra`
// is merged into run.json's details. The folder is claimed (io::claim_output_folder: --overwrite /
// --resume) and created only after the case has been validated and found within the budgets, and removed
// again, if new, when the engine rejects the input with a ConfigError. run.json says "status": "running"
// while the run goes on, "complete" at the end, "incomplete" after an interruption (the command flushes
// what it has) and "failed" after an error; the exception is rethrown. results.nc is written for a complete
// run whose command returned data, when ctx.formats.netcdf (--format).
CommandResult execute(const Command& cmd, Config& cfg, const std::filesystem::path& out_dir, const RunContext& ctx,
                      const nlohmann::json& extra = {});
// execute of a case that plan() has already parsed (defaults written in) and estimated as `planned`: the
// estimate is checked against the budgets, the case is not parsed again (the runs of an ensemble).
CommandResult execute_planned(const Command& cmd, Config& cfg, const Estimate& planned,
                              const std::filesystem::path& out_dir, const RunContext& ctx,
                              const nlohmann::json& extra = {});

// The folder policy a run context asks for (resume wins over overwrite; the CLI forbids both).
FolderPolicy folder_policy(const RunContext& ctx);

// run.json of a run that has started: command, case, "status": "running", pid, and `details` when not
// empty (an ensemble's command, swept keys and values, and seeds: what --resume checks).
void write_run_started(const OutputDir& out, std::string_view command, const std::string& case_file,
                       const nlohmann::json& details = {});

// results.nc (io/netcdf_writer.hpp) of a complete run: `data` plus the global attributes Conventions
// ("CF-1.8"), title, agglo_version, git_hash, command, seed and config (the resolved TOML text).
// `status` other than "complete" (e.g. "incomplete" for the partial results of an interrupted run) is
// added as the global attribute `status`. `file`: another NetCDF file of the run with the same attributes.
void write_results_nc(const OutputDir& out, const Config& cfg, std::string_view command, long long seed,
                      const io::Dataset& data, std::string_view status = "complete",
                      const std::string& file = io::kResultsFile);

// config.resolved.toml and run.json of a finished ("complete") or interrupted ("incomplete") run (also
// used by sweep for its own folder).
void write_run_files(const OutputDir& out, const Config& cfg, std::string_view command, long long seed,
                     double wall_time_s, const nlohmann::json& details, std::string_view status = "complete");
// The same for a run that stopped on an error or an interruption, as far as the disk allows: when the
// files cannot be written (a full disk) run.json is rewritten in place over its own blocks. Never
// throws: the error that stopped the run is the one reported.
void write_stopped_run_files(const OutputDir& out, const Config& cfg, std::string_view command, long long seed,
                             double wall_time_s, const nlohmann::json& details, std::string_view status) noexcept;

}  // namespace agglo::run
