#include "agglo/io/electrostatics_writers.hpp"

#include <fmt/format.h>

#include "agglo/electrostatics/config.hpp"
#include "agglo/io/surface_vtu.hpp"

namespace agglo::io {

nlohmann::json solve_stats(const es::Solver& solver, const es::Problem& p, const es::Solution& sol) {
  nlohmann::json st = {{"solver", solver.name()},
                       {"iterations", sol.stats.iterations},
                       {"residual", sol.stats.residual},
                       {"time_s", sol.stats.seconds},
                       {"degree", sol.stats.degree},
                       {"particles", p.spheres.size()},
                       {"smallest_gap_m", p.spheres.size() > 1 ? es::smallest_gap(p) : 0.0}};
  if (!sol.stats.extra.is_null()) st["extra"] = sol.stats.extra;
  return st;
}

void write_electrostatics(const OutputDir& out, const es::Solver& solver, const es::Problem& p,
                          const es::Solution& sol) {
  out.write("forces.csv", [&](std::ostream& os) {
    os << "id,fx,fy,fz,tx,ty,tz\n";
    for (std::size_t i = 0; i < p.spheres.size(); ++i) {
      const auto& f = sol.force[i];
      const auto& t = sol.torque[i];
      os << fmt::format("{},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n", i, f.x, f.y, f.z, t.x, t.y, t.z);
    }
  });
  out.write_json("energy.json", nlohmann::json{{"energy_J", sol.energy}});
  out.write_json("stats.json", solve_stats(solver, p, sol));
  out.write("surface.vtu", [&](std::ostream& os) { write_surface_vtu(os, solver.surface(), solver.surface_triangles()); });
}

}  // namespace agglo::io
