// agglo breakup CASE.toml: break-up probability vs speed over an ensemble of impact offsets.
#include <chrono>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "agglo/impact/breakup.hpp"
#include "agglo/impact/impact_writers.hpp"
#include "agglo/core/progress.hpp"
#include "command.hpp"

namespace {

agglo::cli::Registration reg([](CLI::App& app) {
  auto args = std::make_shared<agglo::cli::CommonArgs>();
  auto* sub = app.add_subcommand(
      "breakup", "Break-up probability vs speed over an ensemble of impact offsets ([breakup] speeds, samples, "
                 "offset_spread)");
  agglo::cli::add_common_options(*sub, *args);
  sub->callback([args] {
    auto start = std::chrono::steady_clock::now();
    auto cfg = agglo::cli::load_case(*args);
    auto c = agglo::impact::parse_impact_case(cfg);
    cfg.check_unknown_keys();
    auto out = agglo::cli::open_output(*args, "breakup");
    agglo::Progress prog("breakup", true);
    const auto relaxed = agglo::impact::relaxed_agglomerate(c);  // independent of the projectile offset
    auto res = agglo::impact::breakup_probability(
        c.breakup, c.projectile.offset_radii,
        [&c, &relaxed](double v, double offset) {
          auto ck = c;
          ck.projectile.offset_radii = offset;
          return agglo::impact::run_impact(ck, v, nullptr, {}, &relaxed);
        },
        [&](double f) { prog.update(f, 0.0); });
    prog.finish();
    agglo::impact::write_breakup(out, res);
    agglo::cli::write_run_files(out, cfg, "breakup", 0, start);
    agglo::cli::run_plot_script("plot_breakup.py", out);
    auto fmtv = [](double v) { return v < 0.0 ? std::string("not reached") : fmt::format("{:.4f} m/s", v); };
    std::printf("%s: break-up probability at %zu speeds x %zu offsets: v10 = %s, v50 = %s, v90 = %s\n",
                c.name.c_str(), res.points.size(), res.offsets.size(), fmtv(res.v10).c_str(), fmtv(res.v50).c_str(),
                fmtv(res.v90).c_str());
  });
});

}  // namespace
