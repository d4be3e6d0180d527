// agglo electrostatics CASE.toml: one static solve of charged dielectric spheres (MODEL Part B).
// Case: [[particles]] position = [x,y,z] (m), radius (m), charge (C), permittivity (kappa_p);
// [electrostatics] (see src/agglo/electrostatics/config.hpp). Radii are shrunk to r_E (min_gap).
// Writes forces.csv (id,fx,fy,fz,tx,ty,tz in N, N m), energy.json, stats.json, surface.vtu,
// config.resolved.toml, run.json.
#include <chrono>
#include <cstdio>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/electrostatics/config.hpp"
#include "agglo/electrostatics/surface_vtu.hpp"
#include "command.hpp"

namespace {

agglo::cli::Registration reg([](CLI::App& app) {
  auto args = std::make_shared<agglo::cli::CommonArgs>();
  auto* sub = app.add_subcommand("electrostatics", "Static electrostatic solve: forces, torques, energy, surface charge");
  agglo::cli::add_common_options(*sub, *args);
  sub->callback([args] {
    using namespace agglo;
    auto start = std::chrono::steady_clock::now();
    auto cfg = cli::load_case(*args);
    auto root = cfg.root();
    auto ec = es::parse_electrostatics(root.section("electrostatics"));
    auto parts = root.tables("particles");
    if (parts.empty()) root.fail("particles", "at least one [[particles]] entry is required");
    es::Problem p;
    p.medium_permittivity = ec.medium_permittivity;
    p.external_field = ec.external_field;
    for (const auto& s : parts) {
      es::Sphere sp;
      sp.center = s.vec3("position", std::nullopt, Range::any("m"));
      double r = s.number("radius", std::nullopt, Range::positive("m"));
      sp.radius = es::electrostatic_radius(r, ec.min_gap);
      sp.charge = s.number("charge", 0.0, Range::any("C"));
      sp.permittivity = s.number("permittivity", 1.0, Range::positive());
      p.spheres.push_back(sp);
    }
    cfg.check_unknown_keys();
    es::check_particles(p, cfg.file());
    auto out = cli::open_output(*args, "electrostatics");
    auto solver = es::make_solver(ec.options);
    es::Solution sol = solver->solve(p);
    out.write("forces.csv", [&](std::ostream& os) {
      os << "id,fx,fy,fz,tx,ty,tz\n";
      for (std::size_t i = 0; i < p.spheres.size(); ++i) {
        const auto& f = sol.force[i];
        const auto& t = sol.torque[i];
        os << fmt::format("{},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n", i, f.x, f.y, f.z, t.x, t.y, t.z);
      }
    });
    out.write_json("energy.json", nlohmann::json{{"energy_J", sol.energy}});
    nlohmann::json st = {{"solver", solver->name()},
                         {"iterations", sol.stats.iterations},
                         {"residual", sol.stats.residual},
                         {"time_s", sol.stats.seconds},
                         {"degree", sol.stats.degree},
                         {"particles", p.spheres.size()},
                         {"smallest_gap_m", p.spheres.size() > 1 ? es::smallest_gap(p) : 0.0}};
    if (!sol.stats.extra.is_null()) st["extra"] = sol.stats.extra;
    out.write_json("stats.json", st);
    out.write("surface.vtu", [&](std::ostream& os) {
      es::write_surface_vtu(os, solver->surface(), solver->surface_triangles());
    });
    cli::write_run_files(out, cfg, "electrostatics", 0, start);
    std::printf("electrostatics (%s): %zu particles, U = %.6g J, %d iterations, degree %d, %.3g s; outputs in %s\n",
                solver->name().c_str(), p.spheres.size(), sol.energy, sol.stats.iterations, sol.stats.degree,
                sol.stats.seconds, out.path().c_str());
  });
});

}  // namespace
