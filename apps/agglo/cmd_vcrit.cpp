// agglo vcrit CASE.toml: critical break-up velocity by parallel scan + bisection.
#include <chrono>
#include <cstdio>
#include <omp.h>

#include "agglo/impact/impact_writers.hpp"
#include "agglo/core/progress.hpp"
#include "command.hpp"

namespace {

agglo::cli::Registration reg([](CLI::App& app) {
  auto args = std::make_shared<agglo::cli::CommonArgs>();
  auto* sub = app.add_subcommand("vcrit", "Critical break-up velocity of an agglomerate (bisection on speed)");
  agglo::cli::add_common_options(*sub, *args);
  sub->callback([args] {
    auto start = std::chrono::steady_clock::now();
    auto cfg = agglo::cli::load_case(*args);
    auto c = agglo::impact::parse_impact_case(cfg);
    cfg.check_unknown_keys();
    auto out = agglo::cli::open_output(*args, "vcrit");
    agglo::Progress prog("vcrit", true);
    const auto relaxed = agglo::impact::relaxed_agglomerate(c);  // one relaxation for every speed
    auto res = agglo::impact::find_vcrit(
        c.vcrit, omp_get_max_threads(),
        [&c, &relaxed](double v) { return agglo::impact::run_impact(c, v, nullptr, {}, &relaxed); },
        [&](double f) { prog.update(f, 0.0); });
    prog.finish();
    out.write_json("vcrit.json", agglo::impact::vcrit_json(res));
    agglo::cli::write_run_files(out, cfg, "vcrit", 0, start);
    agglo::cli::run_plot_script("plot_vcrit.py", out);
    std::printf("%s: v_crit = %.4f m/s (bracket [%.5f, %.5f], %zu runs)\n", c.name.c_str(), res.v_crit, res.lo,
                res.hi, res.runs.size());
    for (const auto& w : res.warnings) std::printf("  warning: %s\n", w.c_str());
  });
});

}  // namespace
