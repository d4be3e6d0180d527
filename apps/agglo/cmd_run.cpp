// One CLI subcommand per command of the run pipeline (collide, vcrit, breakup, electrostatics,
// acoustic): parse, run, summarise, write, plot. A command's shortcuts (e.g. `collide --speed V`)
// become options that override their config key.
#include <memory>

#include <fmt/format.h>

#include "agglo/run/commands.hpp"
#include "command.hpp"

namespace {

void add_subcommand(CLI::App& app, const agglo::run::Command& cmd) {
  auto args = std::make_shared<agglo::cli::CommonArgs>();
  const auto shortcuts = cmd.shortcuts();
  auto values = std::make_shared<std::vector<std::string>>(shortcuts.size());
  auto* sub = app.add_subcommand(std::string(cmd.name()), std::string(cmd.help()));
  agglo::cli::add_common_options(*sub, *args);
  if (cmd.restartable()) agglo::cli::add_checkpoint_option(*sub, *args);
  for (std::size_t k = 0; k < shortcuts.size(); ++k) {
    const auto* key = shortcuts[k].key;
    sub->add_option(shortcuts[k].flags, (*values)[k],
                    fmt::format("{} [{}] (sets {}; default: the case's value)", key->info().meaning, key->info().unit,
                                key->dotted()));
  }
  sub->callback([args, values, shortcuts, &cmd] {
    agglo::Config cfg = agglo::cli::load_case(*args);
    for (std::size_t k = 0; k < shortcuts.size(); ++k)
      if (!(*values)[k].empty()) cfg.apply_override(fmt::format("{}={}", shortcuts[k].key->dotted(), (*values)[k]));
    const auto out = agglo::cli::output_path(*args, std::string(cmd.name()));
    const auto ctx = agglo::cli::context(*args);
    if (args->dry_run) return agglo::cli::dry_run(cfg.file(), agglo::run::plan(cmd, cfg, ctx), ctx);
    const auto res = agglo::run::execute(cmd, cfg, out, ctx);
    if (ctx.formats.csv) agglo::cli::run_plot_script(res.plot_script, out, res.plot_args);  // plots read the CSV files
  });
}

agglo::cli::Registration reg([](CLI::App& app) {
  for (const auto* cmd : agglo::run::all_commands()) add_subcommand(app, *cmd);
});

}  // namespace
