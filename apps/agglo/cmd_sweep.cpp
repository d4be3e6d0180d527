// `agglo sweep CASE.toml --param KEY --values v1,v2,... [--param KEY2 --values ...] [--command NAME]
// [--seeds N]`: independent runs of any command over a grid of config values, on all cores; writes
// sweep.csv, one folder per case and a plot (scripts/plot_sweep.py). With --seeds N >= 2 every point runs
// N seeds and gets the mean and standard error of every result (run/ensemble_request.hpp).
#include <memory>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/run/ensemble_request.hpp"
#include "command.hpp"

namespace {

struct SweepArgs {
  agglo::cli::CommonArgs common;
  std::vector<std::string> params, values;
  std::string command = "acoustic";
  long long seeds = 1;
};

std::vector<agglo::run::SweepAxis> axes(const SweepArgs& a) {
  if (a.params.size() != a.values.size())
    throw agglo::ConfigError(fmt::format("sweep: {} --param but {} --values; give one --values list per --param",
                                         a.params.size(), a.values.size()));
  std::vector<agglo::run::SweepAxis> ax;
  for (std::size_t k = 0; k < a.params.size(); ++k) ax.push_back({a.params[k], agglo::run::split_values(a.values[k])});
  return ax;
}

void run(const SweepArgs& a) {
  const auto ctx = agglo::cli::context(a.common);
  auto plan = agglo::run::plan_ensemble(
      {a.command, agglo::cli::load_case(a.common), axes(a), a.seeds, agglo::cli::output_path(a.common, "sweep")}, ctx);
  if (a.common.dry_run)
    return agglo::cli::dry_run(plan.request.base.file(), plan.estimate,
                               plan.cmd->seconds_per_step(plan.sweep.configs.front()), ctx);
  agglo::run::execute_ensemble(plan, ctx);
  std::vector<std::string> plot_args;  // the swept keys (--seeds: the seed key is the last)
  for (const auto& x : plan.axes) plot_args.push_back(x.key);
  if (!plan.seeds.empty()) plot_args.insert(plot_args.begin(), "--seeds");
  if (ctx.formats.csv) agglo::cli::run_plot_script("plot_sweep.py", plan.request.folder, plot_args);  // reads sweep.csv
}

agglo::cli::Registration register_sweep([](CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  auto* sub = app.add_subcommand("sweep", "Run any command over a grid of config values, cases in parallel");
  agglo::cli::add_common_options(*sub, a->common);
  sub->add_option("-p,--param", a->params, "Config key to vary, e.g. population.1.diameter (repeatable: a grid)")
      ->required()
      ->take_all();
  sub->add_option("-v,--values", a->values, "Comma-separated values for the matching --param, e.g. 10e-6,20e-6")
      ->required()
      ->take_all();
  sub->add_option("-c,--command", a->command,
                  fmt::format("Command run for each case ({})", fmt::join(agglo::run::command_names(), ", ")))
      ->capture_default_str();
  sub->add_option("--seeds", a->seeds,
                  "Run every point with N seeds (derived from the case's seed and the member index; member 0 is "
                  "the case's own): each point's mean and standard error of every result in point_<index>_<values>/ "
                  "and sweep_ensemble.csv (default 1: one run per point)")
      ->type_name("N");
  sub->callback([a] { run(*a); });
});

}  // namespace
