#include "command.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>
#include <omp.h>

#include "agglo/core/error.hpp"
#include "agglo/io/output_dir.hpp"
#include "agglo/run/ranks.hpp"

namespace agglo::cli {

std::vector<Registrar>& registry() {
  static std::vector<Registrar> r;
  return r;
}

bool& quiet() {
  static bool q = false;
  return q;
}

bool& plots_enabled() {
  static bool on = true;
  return on;
}

namespace {
// --threads: a whole number >= 0 (0 = all cores); the message names the rule, not a numeric bound.
CLI::Validator thread_count() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        std::size_t used = 0;
        long v = -1;
        try {
          v = std::stol(s, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != s.size() || v < 0 || v > 100000)
          return "'" + s + "' is not a whole number of threads from 0 (all cores) to 100000";
        return {};
      },
      "INT>=0");
}

// --format: a comma-separated, non-empty list of csv and netcdf.
CLI::Validator output_formats() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        try {
          (void)run::parse_formats(s);
          return {};
        } catch (const ConfigError& e) {
          return e.what();
        }
      },
      "csv|netcdf|csv,netcdf");
}
}  // namespace

void add_common_options(CLI::App& sub, CommonArgs& args) {
  sub.add_option("case", args.case_file, "Case file (TOML)")->required()->check(CLI::ExistingFile);
  sub.add_option("-o,--out", args.out, "Output folder (default: results/<case>-<command>)");
  sub.add_option("-s,--set", args.sets, "Override a config key: --set section.key=value (repeatable)")
      ->take_all();
  sub.add_option("-j,--threads", args.threads, "OpenMP threads (default: all cores)")->check(thread_count());
  auto* resume = sub.add_flag("--resume", args.resume,
                              "Continue the run in the output folder: ensembles (vcrit, breakup, sweep) reuse the "
                              "finished jobs of its journal.jsonl; collide, acoustic and sectional continue from the "
                              "folder's checkpoint.bin (--checkpoint); electrostatics starts again");
  sub.add_flag("--overwrite", args.overwrite, "Replace the earlier agglo run in the output folder (clears it)")
      ->excludes(resume);
  sub.add_option("--max-steps", args.budget.max_steps, "Step budget in particle-steps (default: AGGLO_MAX_STEPS or 1e12)");
  sub.add_option("--max-memory", args.budget.max_memory, "Memory budget, e.g. 8G (default: AGGLO_MAX_MEMORY or 0.8 x RAM)");
  sub.add_option("--max-output", args.budget.max_output, "Output size budget, e.g. 2G (default: AGGLO_MAX_OUTPUT or 1G)");
  sub.add_flag("--dry-run", args.dry_run, "Validate and print the estimated steps, memory and output; run nothing");
  sub.add_option("--format", args.format,
                 "Result files: csv, netcdf or csv,netcdf (default; CSV/JSON files and results.nc)")
      ->check(output_formats());
}

void add_checkpoint_option(CLI::App& sub, CommonArgs& args) {
  sub.add_option("--checkpoint", args.checkpoint,
                 "Write a checkpoint every INTERVAL simulated seconds into the output folder; --resume continues "
                 "from the last one")
      ->check(CLI::PositiveNumber);
}

Config load_case(const CommonArgs& args) {
  if (args.threads > 0) omp_set_num_threads(args.threads);
  Config cfg = Config::load(args.case_file);
  for (const auto& s : args.sets) cfg.apply_override(s);
  return cfg;
}

std::filesystem::path output_path(const CommonArgs& args, const std::string& command) {
  return args.out.empty() ? default_output_dir(args.case_file, command) : std::filesystem::path(args.out);
}

namespace {
run::CancelToken& interrupt_token() {
  static run::CancelToken t;
  return t;
}
volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_interrupt(int sig) {
  g_signal = sig;
  interrupt_token().cancel();
}
}  // namespace

int interrupt_exit_code() { return 128 + (g_signal != 0 ? static_cast<int>(g_signal) : SIGINT); }

run::RunContext context(const CommonArgs& args) {
  static run::TerminalReporter reporter(quiet());
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  static run::Budgets budgets;
  budgets = run::resolve_budgets(args.budget);
  static run::SilentReporter silent;  // MPI ranks other than 0 print nothing (rank 0 reports for the run)
  run::RunContext ctx;
  ctx.reporter = run::is_output_rank() ? static_cast<run::Reporter*>(&reporter) : &silent;
  ctx.cancel = &interrupt_token();
  ctx.threads = args.threads;
  ctx.resume = args.resume;
  ctx.overwrite = args.overwrite;
  ctx.budgets = &budgets;
  ctx.checkpoint_interval = args.checkpoint;
  ctx.formats = run::parse_formats(args.format);  // validated by the option's check
  return ctx;
}

void dry_run(const std::string& what, const Estimate& e, double seconds_per_step, const run::RunContext& ctx) {
  const auto b = run::budgets_of(ctx);
  if (run::is_output_rank())
    std::printf("%s: valid; estimated cost (dry run: nothing run or written)\n%s%s", one_line(what).c_str(),
                run::describe(e, b).c_str(), run::describe_time(e.steps.value, seconds_per_step).c_str());
  std::fflush(stdout);
  run::check_budgets(e, b, what);
}

PlotsInterrupted::PlotsInterrupted(const std::filesystem::path& f)
    : InterruptedError("interrupted while making the plots"), folder(f) {}

namespace {
// The plot scripts write each PNG as `.NAME.tmp.png` and rename it when complete.
void remove_partial_plots(const std::filesystem::path& out) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(out, ec)) {
    const std::string n = e.path().filename().string();
    if (n.starts_with('.') && n.ends_with(".tmp.png")) std::filesystem::remove(e.path(), ec);
  }
}

// Waits for the child; on an interruption ends it (SIGTERM to its process group) and throws.
// Returns the child's wait status, or -1 if waiting failed.
int wait_for_plots(pid_t pid, const std::filesystem::path& out) {
  int status = 0;
  for (;;) {
    const pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid) return status;
    if (r < 0 && errno != EINTR) return -1;
    if (interrupt_token().cancelled()) {
      kill(-pid, SIGTERM);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
      remove_partial_plots(out);
      throw PlotsInterrupted(out);
    }
    usleep(20000);
  }
}
}  // namespace

void run_plot_script(const std::string& script, const std::filesystem::path& out, const std::vector<std::string>& args) {
  if (!plots_enabled() || script.empty() || !run::is_output_rank()) return;
  namespace fs = std::filesystem;
  fs::path path = fs::path(AGGLO_SOURCE_DIR) / "scripts" / script;
  if (!fs::exists(path)) {
    std::fprintf(stderr, "agglo: warning: plot script %s not found; no plots made\n", path.c_str());
    return;
  }
  std::vector<std::string> words{AGGLO_PYTHON, path.string(), out.string()};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  // Its own process group: a terminal's Ctrl-C reaches agglo only, which then ends the script quietly
  // (a Python traceback would break the one-line message).
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attr, 0);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, words[0].c_str(), nullptr, &attr, argv.data(), environ);
  posix_spawnattr_destroy(&attr);
  const int status = rc == 0 ? wait_for_plots(pid, out) : -1;
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    std::fprintf(stderr, "agglo: warning: plotting failed (%s %s); CSV results are complete\n", AGGLO_PYTHON,
                 path.c_str());
}

}  // namespace agglo::cli
