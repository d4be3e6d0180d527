// agglo electrostatics: one static solve of charged dielectric spheres (docs/model.md Part B).
// Case: [[particles]] position, radius, charge, permittivity; [electrostatics] solver settings.
// Radii are shrunk to the electrostatic radius r_E (min_gap) as in the DEM coupling.
#include <fmt/format.h>

#include "agglo/electrostatics/config.hpp"
#include "agglo/electrostatics/estimate.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/writers/electrostatics.hpp"

namespace agglo::run {

namespace {

class Electrostatics final : public Command {
 public:
  std::string_view name() const override { return "electrostatics"; }
  std::string_view help() const override {
    return "Static electrostatic solve: forces, torques, energy, surface charge";
  }

  void parse(Config& cfg) const override { (void)es::parse_electrostatics_case(cfg); }

  Estimate estimate(Config& cfg, const RunContext&) const override {
    const es::EsCase sc = es::parse_electrostatics_case(cfg);
    return es::static_solve_estimate(sc.settings.options, sc.problem, sc.surface_output);
  }

  // Per solver, one thread, against the bound with every GMRES iteration allowed (real solves stop
  // earlier, so the time is an upper bound too): each solver type's measured rate (registry.hpp).
  double seconds_per_step(Config& cfg) const override {
    auto root = cfg.root();
    const es::EsConfig ec = es::parse_electrostatics(es::solver_keys().t.open(root));
    return es::seconds_per_interaction(ec.options);
  }

  Estimate lower_bound(Config& cfg) const override {
    const auto& keys = settings::electrostatics_settings();
    auto root = cfg.root();
    const es::EsConfig ec = es::parse_electrostatics(es::solver_keys().t.open(root));
    return es::static_solve_lower_bound(ec.options, static_cast<double>(keys.particles.t.elements(root).size()),
                                        keys.output.surface.read(keys.output.t.open(root)));
  }

  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    const es::EsCase sc = es::parse_electrostatics_case(cfg);
    const auto solver = es::make_solver(sc.settings.options);
    const es::Solution sol = solver->solve(sc.problem);
    if (ctx.formats.csv) writers::write_electrostatics(out, *solver, sc.problem, sol, sc.surface_output);
    CommandResult r;
    r.data = std::make_shared<const io::Dataset>(writers::electrostatics_dataset(*solver, sc.problem, sol));
    r.summary = writers::solve_stats(*solver, sc.problem, sol);
    r.summary["energy_J"] = sol.energy;
    ctx.report().info(fmt::format(
        "electrostatics ({}): {} particles, U = {:.6g} J, {} iterations, degree {}, {:.3g} s; outputs in {}",
        solver->name(), sc.problem.spheres.size(), sol.energy, sol.stats.iterations, sol.stats.degree,
        sol.stats.seconds, out.path().string()));
    return r;
  }
};

}  // namespace

const Command& electrostatics_command() {
  static const Electrostatics c;
  return c;
}

}  // namespace agglo::run
