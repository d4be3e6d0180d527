// agglo electrostatics: one static solve of charged dielectric spheres (docs/model.md Part B).
// Case: [[particles]] position, radius, charge, permittivity; [electrostatics] solver settings.
// Radii are shrunk to the electrostatic radius r_E (min_gap) as in the DEM coupling.
#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/electrostatics/config.hpp"
#include "agglo/io/electrostatics_writers.hpp"
#include "agglo/run/commands.hpp"

namespace agglo::run {

namespace {

struct StaticCase {
  es::EsConfig settings;
  es::Problem problem;
};

StaticCase parse_static_case(Config& cfg) {
  auto root = cfg.root();
  StaticCase sc;
  sc.settings = es::parse_electrostatics(root.section("electrostatics"));
  auto parts = root.tables("particles");
  if (parts.empty()) root.fail("particles", "at least one [[particles]] entry is required");
  sc.problem.medium_permittivity = sc.settings.medium_permittivity;
  sc.problem.external_field = sc.settings.external_field;
  for (const auto& s : parts) {
    es::Sphere sp;
    sp.center = s.vec3("position", std::nullopt, Range::any("m"));
    const double r = s.number("radius", std::nullopt, Range::positive("m"));
    sp.radius = es::electrostatic_radius(r, sc.settings.min_gap);
    sp.charge = s.number("charge", 0.0, Range::any("C"));
    sp.permittivity = s.number("permittivity", 1.0, Range::positive());
    sc.problem.spheres.push_back(sp);
  }
  cfg.check_unknown_keys();
  es::check_particles(sc.problem, cfg.file());
  return sc;
}

class Electrostatics final : public Command {
 public:
  std::string_view name() const override { return "electrostatics"; }
  std::string_view help() const override {
    return "Static electrostatic solve: forces, torques, energy, surface charge";
  }

  void parse(Config& cfg) const override { (void)parse_static_case(cfg); }

  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    const StaticCase sc = parse_static_case(cfg);
    const auto solver = es::make_solver(sc.settings.options);
    const es::Solution sol = solver->solve(sc.problem);
    io::write_electrostatics(out, *solver, sc.problem, sol);
    CommandResult r;
    r.summary = io::solve_stats(*solver, sc.problem, sol);
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
