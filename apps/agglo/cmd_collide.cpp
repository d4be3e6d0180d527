// agglo collide CASE.toml: one collision run with time series, VTK snapshots, result.json, plots.
#include <chrono>
#include <cstdio>

#include <fmt/format.h>

#include "agglo/impact/impact_writers.hpp"
#include "agglo/core/progress.hpp"
#include "command.hpp"

namespace {

agglo::cli::Registration reg([](CLI::App& app) {
  auto args = std::make_shared<agglo::cli::CommonArgs>();
  auto speed = std::make_shared<double>(-1.0);
  auto* sub = app.add_subcommand("collide", "One particle-agglomerate collision (DEM, optional electrostatics)");
  agglo::cli::add_common_options(*sub, *args);
  sub->add_option("-v,--speed", *speed, "Projectile speed [m/s] (default: projectile.speed of the case)");
  sub->callback([args, speed] {
    auto start = std::chrono::steady_clock::now();
    auto cfg = agglo::cli::load_case(*args);
    if (*speed >= 0.0) cfg.apply_override(fmt::format("projectile.speed={}", *speed));
    auto c = agglo::impact::parse_impact_case(cfg);
    cfg.check_unknown_keys();
    auto out = agglo::cli::open_output(*args, "collide");
    agglo::impact::Recorder rec;
    agglo::Progress prog("collide", true);
    auto res = agglo::impact::run_impact(c, c.projectile.speed, &rec,
                                               [&](double f, double t) { prog.update(f, t); });
    prog.finish();
    agglo::impact::write_timeseries(out, rec);
    agglo::impact::write_snapshots(out, rec);
    out.write_json("result.json", agglo::impact::outcome_json(res));
    agglo::cli::write_run_files(out, cfg, "collide", 0, start);
    agglo::cli::run_plot_script("plot_collision.py", out);
    std::printf("%s: v_in = %.6g m/s -> %s (%zu fragment(s)); outputs in %s\n", c.name.c_str(), res.speed,
                res.broken ? "BROKEN" : (res.undecided ? "undecided" : "not broken"), res.fragments.size(),
                out.path().c_str());
  });
});

}  // namespace
