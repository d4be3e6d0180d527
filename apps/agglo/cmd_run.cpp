// One CLI subcommand per command of the run pipeline (collide, vcrit, breakup, electrostatics,
// acoustic): parse, run, summarise, write, plot. `collide --speed V` is a shortcut for the
// projectile speed.
#include <memory>

#include <fmt/format.h>

#include "agglo/core/settings_impact.hpp"
#include "agglo/run/commands.hpp"
#include "command.hpp"

namespace {

const agglo::settings::Real& speed_key() { return agglo::settings::impact_settings().projectile.speed; }

void add_subcommand(CLI::App& app, const agglo::run::Command& cmd) {
  auto args = std::make_shared<agglo::cli::CommonArgs>();
  auto speed = std::make_shared<double>(-1.0);
  auto* sub = app.add_subcommand(std::string(cmd.name()), std::string(cmd.help()));
  agglo::cli::add_common_options(*sub, *args);
  if (cmd.name() == "collide")
    sub->add_option("-v,--speed", *speed,
                    fmt::format("Projectile speed [m/s] (default: {} of the case)", speed_key().dotted()));
  sub->callback([args, speed, &cmd] {
    agglo::Config cfg = agglo::cli::load_case(*args);
    if (*speed >= 0.0) cfg.apply_override(fmt::format("{}={}", speed_key().dotted(), *speed));
    const auto out = agglo::cli::output_path(*args, std::string(cmd.name()));
    const auto res = agglo::run::execute(cmd, cfg, out, agglo::cli::context(*args));
    agglo::cli::run_plot_script(res.plot_script, out, res.plot_args);
  });
}

agglo::cli::Registration reg([](CLI::App& app) {
  for (const auto* cmd : agglo::run::all_commands()) add_subcommand(app, *cmd);
});

}  // namespace
