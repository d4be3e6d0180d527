#pragma once
// The CLI front end over the run pipeline (src/agglo/run): options every command takes (CASE.toml,
// --out, --set, --threads, --resume), the terminal reporter, Ctrl-C as a cancel token, and the
// plot scripts run after a command.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "agglo/core/config.hpp"
#include "agglo/core/error.hpp"
#include "agglo/run/command.hpp"

namespace agglo::cli {

struct CommonArgs {
  std::string case_file;
  std::string out;
  std::vector<std::string> sets;
  int threads = 0;
  bool resume = false;
  bool overwrite = false;
  run::BudgetArgs budget;  // --max-steps, --max-memory, --max-output
  bool dry_run = false;    // --dry-run
  std::string format = "csv,netcdf";  // --format: comma-separated csv, netcdf
  double checkpoint = 0.0;            // --checkpoint [simulated s] (restartable commands only)
};

// Adds CASE.toml, --out, --set, --threads, --resume, --overwrite, the budgets and --dry-run to a subcommand.
void add_common_options(CLI::App& sub, CommonArgs& args);

// --checkpoint SECONDS on a subcommand whose command writes checkpoints.
void add_checkpoint_option(CLI::App& sub, CommonArgs& args);

// Loads the case and applies --set overrides (ConfigError on any problem); sets the OpenMP threads.
Config load_case(const CommonArgs& args);

// Output folder from --out or the default results/<case>-<command>.
std::filesystem::path output_path(const CommonArgs& args, const std::string& command);

// The run context of the CLI: terminal reporter (quiet with -q), Ctrl-C cancels, the budgets
// (command line, environment, defaults).
run::RunContext context(const CommonArgs& args);

// --dry-run: prints the estimates of `what` (a validated case) against the budgets on stdout; a
// ConfigError if one is exceeded (exit 2), else returns (exit 0). Nothing is created.
void dry_run(const std::string& what, const Estimate& e, double seconds_per_step, const run::RunContext& ctx);

// Exit code after an interruption: 128 + the signal (130 for SIGINT / Ctrl-C, 143 for SIGTERM).
int interrupt_exit_code();

// Global switches (-q, --no-plots).
bool& quiet();
bool& plots_enabled();

// Runs `python3 scripts/<script> <outdir> [args...]` to make PNG plots from the CSV outputs, as a child
// process in its own process group. Plotting is best effort: a missing matplotlib gives a warning, never
// a failed run. Ctrl-C or SIGTERM while it runs ends the script within about 20 ms, removes its
// temporary files (`.*.tmp.png`) and throws PlotsInterrupted: the results are complete, the plots not.
void run_plot_script(const std::string& script, const std::filesystem::path& out,
                     const std::vector<std::string>& args = {});

// Interrupted while making the plots of a finished run (exit code as any interruption).
struct PlotsInterrupted : InterruptedError {
  explicit PlotsInterrupted(const std::filesystem::path& folder);
  std::filesystem::path folder;
};

// Subcommands register themselves from their own file: `Registration reg([](CLI::App& app) {...});`
using Registrar = std::function<void(CLI::App&)>;
std::vector<Registrar>& registry();
struct Registration {
  explicit Registration(Registrar r) { registry().push_back(std::move(r)); }
};

}  // namespace agglo::cli
