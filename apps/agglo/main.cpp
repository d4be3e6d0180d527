// agglo command-line front end. Exit codes: 0 ok, 1 internal error, 2 bad input, 3 numerical failure or
// invalid run,
// 130 interrupted by SIGINT (Ctrl-C), 143 by SIGTERM.
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <string>
#include <exception>
#include <memory>

#include <CLI/CLI.hpp>
#include <omp.h>
#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/core/version.hpp"
#include "agglo/mpi/comm.hpp"
#include "agglo/run/ensemble.hpp"
#include "agglo/run/ranks.hpp"
#include "command.hpp"

namespace {
// The line a rank other than 0 did not print (see report()).
std::string& unprinted() {
  static std::string line;
  return line;
}

// Only rank 0 of an MPI run prints errors: every rank meets the same error in the normal course (each
// runs the pipeline, and ensemble outcomes are shared), so a refused case reads as one line as without
// MPI. Another rank keeps its line and prints it only if it failed alone (see main).
template <class... Args>
void report(const char* format, Args... args) {
  if (agglo::run::is_output_rank()) {
    std::fprintf(stderr, format, args...);
    return;
  }
  const int n = std::snprintf(nullptr, 0, format, args...);
  std::string line(static_cast<std::size_t>(std::max(n, 0)), '\0');
  std::snprintf(line.data(), line.size() + 1, format, args...);
  unprinted() = line;
}

// Parses the command line and runs the command; the exit code.
int run_cli(int argc, char** argv) {
  CLI::App app{
      "agglo - adhesive DEM with surface-resolved electrostatics, and DSMC acoustic agglomeration.\n"
      "Run `agglo <command> --help` for the options of a command."};
  app.set_version_flag("-V,--version", fmt::format("agglo {} (git {})", agglo::kVersion, agglo::kGitHash));
  app.add_flag_callback("-q,--quiet", [] { agglo::cli::quiet() = true; }, "No progress line on stderr");
  app.add_flag_callback("--no-plots", [] { agglo::cli::plots_enabled() = false; }, "Do not run the matplotlib plot scripts");
  app.require_subcommand(1);
  app.fallthrough();
  for (auto& reg : agglo::cli::registry()) reg(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    report("agglo: error: %s (see --help)\n", agglo::one_line(e.what()).c_str());
    return 2;
  } catch (const agglo::ConfigError& e) {
    report("agglo: error: %s\n", agglo::one_line(e.what()).c_str());
    return 2;
  } catch (const agglo::InvalidRunError& e) {  // before its base class
    report("agglo: invalid run: %s\n", agglo::one_line(e.what()).c_str());
    return 3;
  } catch (const agglo::NumericalError& e) {
    report("agglo: numerical failure: %s\n", agglo::one_line(e.what()).c_str());
    return 3;
  } catch (const agglo::cli::PlotsInterrupted& e) {  // before its base class
    report("agglo: %s; the results in %s are complete (run.json), the plots are not (rerun without Ctrl-C, or "
           "use --no-plots)\n", e.what(), e.folder.string().c_str());
    return agglo::cli::interrupt_exit_code();
  } catch (const agglo::InterruptedError& e) {
    if (e.before_output) {
      report("agglo: %s while the case was read; nothing was written\n", agglo::one_line(e.what()).c_str());
      return agglo::cli::interrupt_exit_code();
    }
    report("agglo: %s; the results so far are in the output folder, marked incomplete in run.json "
           "(ensembles keep their finished jobs in journal.jsonl); rerun with --resume to continue\n",
           agglo::one_line(e.what()).c_str());
    return agglo::cli::interrupt_exit_code();
  } catch (const std::exception& e) {
    report("agglo: internal error: %s\n", agglo::one_line(e.what()).c_str());
    return 1;
  }
  return 0;
}

// Seconds a failed rank waits for the others at the end before it ends them all (AGGLO_MPI_EXIT_TIMEOUT).
double exit_timeout() {
  const char* v = std::getenv("AGGLO_MPI_EXIT_TIMEOUT");
  const double t = v ? std::atof(v) : 0.0;
  return t > 0.0 ? t : 60.0;
}

}  // namespace

// apps/agglo/omp_wait/omp_wait.cpp: sets short OpenMP spin waits before libgomp starts (referenced so
// that the linker keeps it).
extern "C" int agglo_omp_wait_linked();

int main(int argc, char** argv) {
  if (agglo_omp_wait_linked() != 1) return 1;
  std::unique_ptr<agglo::mpi::Session> mpi;  // MPI only when started by mpirun (docs/scaling.md)
  try {
    mpi = std::make_unique<agglo::mpi::Session>(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "agglo: error: %s\n", agglo::one_line(e.what()).c_str());
    return 2;
  }
  // Under mpirun the default thread count (no --threads) shares this machine's cores among its ranks.
  if (agglo::mpi::local_size() > 1) omp_set_num_threads(agglo::run::resolve_threads(0));
  const int code = run_cli(argc, argv);
  // Every rank meets the same outcome in the normal course; a failure met by one rank alone must not
  // leave the others waiting for it forever (docs/scaling.md, "Failures").
  if (agglo::mpi::size() > 1)
    agglo::mpi::finish(code, exit_timeout(), [] {  // this rank failed alone: say why before all end
      std::fprintf(stderr, "[rank %d of %d] %s", agglo::mpi::rank(), agglo::mpi::size(), unprinted().c_str());
    });
  return code;
}
