// `agglo sweep CASE.toml --param KEY --values v1,v2,... [--param KEY2 --values ...] [--command NAME]`:
// independent runs of any command over a grid of config values, on all cores; writes sweep.csv, one
// folder per case and a plot (scripts/plot_sweep.py).
#include <memory>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/run/sweep.hpp"
#include "command.hpp"

namespace {

struct SweepArgs {
  agglo::cli::CommonArgs common;
  std::vector<std::string> params, values;
  std::string command = "acoustic";
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
  const auto& cmd = agglo::run::find_command(a.command);
  agglo::Config base = agglo::cli::load_case(a.common);
  const auto ax = axes(a);
  const auto path = agglo::cli::output_path(a.common, "sweep");
  auto plan = agglo::run::plan_sweep(cmd, base, ax);  // every case validated before the folder is made
  const auto ctx = agglo::cli::context(a.common);
  const auto cost = agglo::run::sweep_estimate(cmd, plan, ctx);
  if (a.common.dry_run) return agglo::cli::dry_run(base.file(), cost, ctx);
  nlohmann::json details = {{"param", a.params.size() == 1 ? nlohmann::json(a.params[0]) : nlohmann::json(a.params)},
                            {"values", ax.size() == 1 ? nlohmann::json(ax[0].values) : nlohmann::json(a.values)},
                            {"command", a.command}};
  agglo::run::execute_sweep(cmd, base, ax, plan, path, ctx, details);
  std::vector<std::string> plot_args;  // the swept keys
  for (const auto& x : ax) plot_args.push_back(x.key);
  if (ctx.formats.csv) agglo::cli::run_plot_script("plot_sweep.py", path, plot_args);  // the plots read sweep.csv
}

agglo::cli::Registration reg([](CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  auto* sub = app.add_subcommand("sweep", "Run any command over a grid of config values, cases in parallel");
  agglo::cli::add_common_options(*sub, a->common);
  sub->add_option("-p,--param", a->params, "Config key to vary, e.g. population.1.diameter (repeatable: a grid)")
      ->required()
      ->take_all();
  sub->add_option("-v,--values", a->values, "Comma-separated values for the matching --param, e.g. 10e-6,20e-6")
      ->required()
      ->take_all();
  sub->add_option("-c,--command", a->command, "Command run for each case (collide, vcrit, breakup, electrostatics, "
                                              "acoustic)")
      ->capture_default_str();
  sub->callback([a] { run(*a); });
});

}  // namespace
