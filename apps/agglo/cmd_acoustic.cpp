// `agglo acoustic CASE.toml --out DIR`: DSMC acoustic agglomeration with droplets (MODEL Part C).
#include <chrono>
#include <memory>

#include "agglo/acoustics/run.hpp"
#include "agglo/core/progress.hpp"
#include "command.hpp"

namespace {

agglo::cli::Registration reg([](CLI::App& app) {
  auto args = std::make_shared<agglo::cli::CommonArgs>();
  auto* sub = app.add_subcommand("acoustic", "DSMC acoustic agglomeration of fine particles with droplets (seed 002)");
  agglo::cli::add_common_options(*sub, *args);
  sub->callback([args] {
    const auto start = std::chrono::steady_clock::now();
    agglo::Config cfg = agglo::cli::load_case(*args);
    agglo::OutputDir out = agglo::cli::open_output(*args, "acoustic");
    agglo::acoustics::RunOptions opt;
    opt.progress = !agglo::Progress::quiet();
    const nlohmann::json summary = agglo::acoustics::run_acoustic(cfg, out, opt);
    const long long seed = cfg.root().integer("seed", 1, 0, INT64_MAX);
    agglo::cli::write_run_files(out, cfg, "acoustic", seed, start, summary);
    if (cfg.root().section("output").boolean("plots", true)) agglo::cli::run_plot_script("plot_acoustic.py", out);
  });
});

}  // namespace
