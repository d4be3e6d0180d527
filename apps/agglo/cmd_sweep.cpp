// `agglo sweep CASE.toml --param KEY --values v1,v2,... [--command acoustic]`: independent runs of a
// command over the values of one config key, on all cores; writes sweep.csv, one folder per case and
// plots (scripts/plot_sweep.py).
#include <chrono>
#include <map>
#include <memory>

#include <fmt/format.h>

#include "agglo/acoustics/case_config.hpp"
#include "agglo/acoustics/run.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/progress.hpp"
#include "agglo/sweep/sweep.hpp"
#include "command.hpp"

namespace {

struct SweepArgs {
  agglo::cli::CommonArgs common;
  std::string param, values, command = "acoustic";
};

struct Runner {
  agglo::sweep::CaseRunner run;
  std::function<void(agglo::Config&)> validate;
  std::string plot;  // per-case plot script ("" = none)
};

std::map<std::string, Runner> runners() {
  std::map<std::string, Runner> m;
  m["acoustic"] = Runner{
      [](agglo::Config& cfg, const agglo::OutputDir& out, const agglo::sweep::SweepCase& c) {
        const auto start = std::chrono::steady_clock::now();
        agglo::acoustics::RunOptions opt;
        opt.progress = false;
        nlohmann::json s = agglo::acoustics::run_acoustic(cfg, out, opt);
        const long long seed = cfg.root().integer("seed", 1, 0, INT64_MAX);
        nlohmann::json extra = s;
        extra["sweep_assignment"] = c.assignment;
        agglo::cli::write_run_files(out, cfg, "acoustic", seed, start, extra);
        return s;
      },
      [](agglo::Config& cfg) { (void)agglo::acoustics::parse_acoustic_case(cfg); }, "plot_acoustic.py"};
  return m;
}

agglo::cli::Registration reg([](CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  auto* sub = app.add_subcommand("sweep", "Run a command over the values of one config key, cases in parallel");
  agglo::cli::add_common_options(*sub, a->common);
  sub->add_option("-p,--param", a->param, "Config key to vary, e.g. population.1.diameter")->required();
  sub->add_option("-v,--values", a->values, "Comma-separated values, e.g. 10e-6,20e-6,30e-6")->required();
  sub->add_option("-c,--command", a->command, "Command run for each case (acoustic)")->capture_default_str();
  sub->callback([a] {
    const auto start = std::chrono::steady_clock::now();
    auto all = runners();
    auto it = all.find(a->command);
    if (it == all.end()) throw agglo::ConfigError(fmt::format("--command '{}': not sweepable (available: acoustic)", a->command));
    agglo::Config base = agglo::cli::load_case(a->common);
    const auto values = agglo::sweep::split_values(a->values);
    agglo::OutputDir out = agglo::cli::open_output(a->common, "sweep");
    const auto summaries = agglo::sweep::run_sweep(base, a->param, values, out, it->second.run, it->second.validate,
                                                   a->common.threads, !agglo::Progress::quiet());
    agglo::sweep::write_table(out, a->param, values, summaries);
    nlohmann::json extra = {{"param", a->param}, {"values", values}, {"command", a->command}};
    agglo::cli::write_run_files(out, base, "sweep", base.root().integer("seed", 1, 0, INT64_MAX), start, extra);
    agglo::cli::run_plot_script("plot_sweep.py", out, {a->param});
  });
});

}  // namespace
