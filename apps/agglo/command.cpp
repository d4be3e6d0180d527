#include "command.hpp"

#include <omp.h>

namespace agglo::cli {

std::vector<Registrar>& registry() {
  static std::vector<Registrar> r;
  return r;
}

void add_common_options(CLI::App& sub, CommonArgs& args) {
  sub.add_option("case", args.case_file, "Case file (TOML)")->required()->check(CLI::ExistingFile);
  sub.add_option("-o,--out", args.out, "Output folder (default: results/<case>-<command>)");
  sub.add_option("-s,--set", args.sets, "Override a config key: --set section.key=value (repeatable)")
      ->take_all();
  sub.add_option("-j,--threads", args.threads, "OpenMP threads (default: all cores)")->check(CLI::NonNegativeNumber);
}

Config load_case(const CommonArgs& args) {
  if (args.threads > 0) omp_set_num_threads(args.threads);
  Config cfg = Config::load(args.case_file);
  for (const auto& s : args.sets) cfg.apply_override(s);
  return cfg;
}

OutputDir open_output(const CommonArgs& args, const std::string& command) {
  return OutputDir(args.out.empty() ? default_output_dir(args.case_file, command) : std::filesystem::path(args.out));
}

void write_run_files(const OutputDir& out, const Config& cfg, const std::string& command, long long seed,
                     std::chrono::steady_clock::time_point start, nlohmann::json extra) {
  out.write_text("config.resolved.toml", cfg.resolved_toml());
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto meta = run_metadata(command, cfg.file(), seed, wall);
  if (!extra.is_null() && !extra.empty()) meta["details"] = extra;
  out.write_json("run.json", meta);
}

}  // namespace agglo::cli

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace agglo::cli {

bool& plots_enabled() {
  static bool on = true;
  return on;
}

void run_plot_script(const std::string& script, const OutputDir& out, const std::vector<std::string>& args) {
  if (!plots_enabled()) return;
  namespace fs = std::filesystem;
  fs::path path = fs::path(AGGLO_SOURCE_DIR) / "scripts" / script;
  if (!fs::exists(path)) {
    std::fprintf(stderr, "agglo: warning: plot script %s not found; no plots made\n", path.c_str());
    return;
  }
  auto quote = [](const std::string& s) {
    std::string q = "'";
    for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  std::string cmd = quote(AGGLO_PYTHON) + " " + quote(path.string()) + " " + quote(out.path().string());
  for (const auto& a : args) cmd += " " + quote(a);
  int rc = std::system(cmd.c_str());
  if (rc != 0) std::fprintf(stderr, "agglo: warning: plotting failed (%s); CSV results are complete\n", cmd.c_str());
}

}  // namespace agglo::cli
