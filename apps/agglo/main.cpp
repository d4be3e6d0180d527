// agglo command-line front end. Exit codes: 0 ok, 1 internal error, 2 bad input, 3 numerical failure,
// 130 interrupted by SIGINT (Ctrl-C), 143 by SIGTERM.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/core/version.hpp"
#include "command.hpp"

int main(int argc, char** argv) {
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
    std::fprintf(stderr, "agglo: error: %s (see --help)\n", agglo::one_line(e.what()).c_str());
    return 2;
  } catch (const agglo::ConfigError& e) {
    std::fprintf(stderr, "agglo: error: %s\n", agglo::one_line(e.what()).c_str());
    return 2;
  } catch (const agglo::NumericalError& e) {
    std::fprintf(stderr, "agglo: numerical failure: %s\n", agglo::one_line(e.what()).c_str());
    return 3;
  } catch (const agglo::InterruptedError& e) {
    std::fprintf(stderr, "agglo: %s; the results so far are in the output folder, marked incomplete in run.json "
                 "(ensembles keep their finished jobs in journal.jsonl); rerun with --resume to continue\n",
                 agglo::one_line(e.what()).c_str());
    return agglo::cli::interrupt_exit_code();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "agglo: internal error: %s\n", agglo::one_line(e.what()).c_str());
    return 1;
  }
  return 0;
}
