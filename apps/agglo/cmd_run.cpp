// One CLI subcommand per command of the run pipeline (collide, vcrit, breakup, electrostatics,
// acoustic): parse, run, summarise, write, plot. A command's shortcuts (e.g. `collide --speed V`)
// become options that override their config key. A command with a random seed (Command::seed_key)
// takes `--seeds N`: N >= 2 runs a seed ensemble (a seeded sweep with no axes, run/ensemble_request.hpp),
// N = 1 the single run.
#include <charconv>
#include <memory>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/run/ensemble_request.hpp"
#include "command.hpp"

namespace {

// --seeds: a whole number (>= 1 is checked by run::plan_ensemble).
long long seed_count(const std::string& text) {
  long long n = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size())
    throw agglo::ConfigError(
        fmt::format("--seeds '{}': the number of ensemble members must be a whole number >= 1", text));
  return n;
}

// --seeds N >= 2: the seeded ensemble of the case, with no axes (run/ensemble_request.hpp).
void run_seed_ensemble(const agglo::run::Command& cmd, agglo::Config cfg, const agglo::cli::CommonArgs& args,
                       long long n) {
  const auto ctx = agglo::cli::context(args);
  auto plan = agglo::run::plan_ensemble(
      {std::string(cmd.name()), std::move(cfg), {}, n, agglo::cli::output_path(args, std::string(cmd.name()))}, ctx);
  if (args.dry_run)
    return agglo::cli::dry_run(plan.request.base.file(), plan.estimate,
                               cmd.seconds_per_step(plan.sweep.configs.front()), ctx);
  agglo::run::execute_ensemble(plan, ctx);
  if (ctx.formats.csv) agglo::cli::run_plot_script("plot_ensemble.py", plan.request.folder);
}

void add_subcommand(CLI::App& app, const agglo::run::Command& cmd) {
  auto args = std::make_shared<agglo::cli::CommonArgs>();
  auto seeds = std::make_shared<std::string>("1");
  const auto shortcuts = cmd.shortcuts();
  auto values = std::make_shared<std::vector<std::string>>(shortcuts.size());
  auto* sub = app.add_subcommand(std::string(cmd.name()), std::string(cmd.help()));
  agglo::cli::add_common_options(*sub, *args);
  if (cmd.restartable()) agglo::cli::add_checkpoint_option(*sub, *args);
  if (cmd.seed_key())
    sub->add_option("--seeds", *seeds,
                    fmt::format("Seed ensemble of N members (seeds derived from {} and the member index): member "
                                "folders, mean and standard error of every result (default 1: the single run)",
                                cmd.seed_key()->dotted()))
        ->type_name("N");
  for (std::size_t k = 0; k < shortcuts.size(); ++k) {
    const auto* key = shortcuts[k].key;
    sub->add_option(shortcuts[k].flags, (*values)[k],
                    fmt::format("{} [{}] (sets {}; default: the case's value)", key->info().meaning, key->info().unit,
                                key->dotted()));
  }
  sub->callback([args, values, seeds, shortcuts, &cmd] {
    const long long n = seed_count(*seeds);
    agglo::Config cfg = agglo::cli::load_case(*args);
    for (std::size_t k = 0; k < shortcuts.size(); ++k)
      if (!(*values)[k].empty()) cfg.apply_override(fmt::format("{}={}", shortcuts[k].key->dotted(), (*values)[k]));
    if (n != 1) return run_seed_ensemble(cmd, std::move(cfg), *args, n);
    const auto out = agglo::cli::output_path(*args, std::string(cmd.name()));
    const auto ctx = agglo::cli::context(*args);
    if (args->dry_run) {
      const auto e = agglo::run::plan(cmd, cfg, ctx);
      return agglo::cli::dry_run(cfg.file(), e, cmd.seconds_per_step(cfg), ctx);
    }
    const auto res = agglo::run::execute(cmd, cfg, out, ctx);
    if (ctx.formats.csv) agglo::cli::run_plot_script(res.plot_script, out, res.plot_args);  // plots read the CSV files
  });
}

agglo::cli::Registration register_run_commands([](CLI::App& app) {
  for (const auto* cmd : agglo::run::all_commands()) add_subcommand(app, *cmd);
});

}  // namespace
