#pragma once
// Shared plumbing of the CLI commands: registration, the common options every command takes
// (CASE.toml, --out, --set, --quiet, --threads) and the run epilogue (config.resolved.toml, run.json).
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "agglo/core/config.hpp"
#include "agglo/core/output.hpp"

namespace agglo::cli {

using Registrar = std::function<void(CLI::App&)>;
std::vector<Registrar>& registry();

struct Registration {
  explicit Registration(Registrar r) { registry().push_back(std::move(r)); }
};

struct CommonArgs {
  std::string case_file;
  std::string out;
  std::vector<std::string> sets;
  int threads = 0;
};

// Adds CASE.toml, --out, --set and --threads to a subcommand.
void add_common_options(CLI::App& sub, CommonArgs& args);

// Loads the case and applies --set overrides (ConfigError on any problem).
Config load_case(const CommonArgs& args);

// Output folder from --out or the default results/<case>-<command>.
OutputDir open_output(const CommonArgs& args, const std::string& command);

// Writes config.resolved.toml and run.json.
void write_run_files(const OutputDir& out, const Config& cfg, const std::string& command, long long seed,
                     std::chrono::steady_clock::time_point start, nlohmann::json extra = {});

}  // namespace agglo::cli

namespace agglo::cli {
// Runs `python3 scripts/<script> <outdir> [args...]` to make PNG plots from the CSV outputs.
// Plotting is best effort: a missing matplotlib gives a warning, never a failed run.
bool& plots_enabled();  // global --no-plots switch
void run_plot_script(const std::string& script, const OutputDir& out, const std::vector<std::string>& args = {});
}  // namespace agglo::cli
