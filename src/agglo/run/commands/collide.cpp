// agglo collide: one particle-agglomerate impact with time series, VTK snapshots and result.json.
#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/core/settings_impact.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/estimate.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/impact_run.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/run/commands/collide_checkpoint.hpp"
#include "agglo/run/commands/impact_command.hpp"
#include "agglo/writers/impact.hpp"

namespace agglo::run {

namespace {

class Collide final : public ImpactCommand {
 public:
  std::string_view name() const override { return "collide"; }
  std::vector<Shortcut> shortcuts() const override {
    return {{"-v,--speed", &settings::impact_settings().projectile.speed}};
  }
  std::string_view help() const override { return "One particle-agglomerate collision (DEM, optional electrostatics)"; }
  bool restartable() const override { return true; }

  Estimate estimate(Config& cfg, const RunContext&) const override {
    return impact::collide_estimate(impact_case(cfg));
  }

  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    const auto c = impact_case(cfg);
    impact::Recorder rec;
    // Cancellation is seen at step boundaries (checkpoints.at_boundary), where the state is complete.
    auto progress = [&](double f, double t) { ctx.report().progress("collide", f, t); };
    CollideCheckpoints checkpoints(*this, cfg, out, ctx);
    const auto resumed = checkpoints.resume_state();
    impact::ImpactOutcome res;
    try {
      // A resumed run replaces the launch state, so the (possibly long) relaxation is skipped.
      impact::ImpactRun run(c, resumed ? impact::build_agglomerate(c) : relaxed_target(c, ctx),
                            c.projectile.speed, &rec, progress);
      if (resumed) run.restore(*resumed);
      res = run.run([&](const impact::ImpactRun& r) { checkpoints.at_boundary(r); });
      checkpoints.at_end(run);
    } catch (const InterruptedError&) {  // flush the history so far; run.json marks the run incomplete
      if (ctx.formats.csv) writers::write_timeseries(out, rec);
      if (ctx.formats.csv) writers::write_snapshots(out, rec);
      if (ctx.formats.netcdf) write_results_nc(out, cfg, name(), 0, writers::collide_dataset(rec, nullptr), "incomplete");
      throw;
    }
    CommandResult r;
    r.summary = writers::outcome_json(res);
    if (ctx.formats.csv) {
      writers::write_timeseries(out, rec);
      writers::write_snapshots(out, rec);
      out.write_json("result.json", r.summary);
    }
    r.data = std::make_shared<const io::Dataset>(writers::collide_dataset(rec, &res));
    r.plot_script = "plot_collision.py";
    ctx.report().info(fmt::format("{}: v_in = {:.6g} m/s -> {} ({} fragment(s)); outputs in {}", c.name, res.speed,
                                  res.broken ? "BROKEN" : (res.undecided ? "undecided" : "not broken"),
                                  res.fragments.size(), out.path().string()));
    return r;
  }
};

}  // namespace

const Command& collide_command() {
  static const Collide c;
  return c;
}

}  // namespace agglo::run
