#include "agglo/writers/electrostatics.hpp"

#include "agglo/electrostatics/config.hpp"
#include "agglo/io/dataset_scalars.hpp"
#include "agglo/writers/surface_vtu.hpp"

namespace agglo::writers {

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

namespace {
// 3-vectors as (row, xyz) values.
template <class Rows, class F>
std::vector<double> xyz(const Rows& rows, F vec) {
  std::vector<double> out;
  for (const auto& r : rows) {
    const Vec3 x = vec(r);
    out.insert(out.end(), {x.x, x.y, x.z});
  }
  return out;
}
Vec3 same(const Vec3& v) { return v; }
}  // namespace

io::Table forces_table(const es::Problem& p, const es::Solution& sol) {
  using S = es::Sphere;
  const auto& s = p.spheres;
  io::Table t("forces.csv", {{"particle", s.size()}}, "{:.12g}");
  t.add_dim("xyz", 3);
  std::vector<std::int64_t> id;
  for (std::size_t i = 0; i < s.size(); ++i) id.push_back(static_cast<std::int64_t>(i));
  t.integer("particle", "1", "particle index (forces.csv id)", id).header({"id"});
  t.real("position", "m", "sphere centre", xyz(s, [](const S& x) { return x.center; }))
      .over({"particle", "xyz"})
      .header({});
  t.real("radius", "m", "electrostatic radius", io::reals_of(s, [](const S& x) { return x.radius; })).header({});
  t.real("charge", "C", "free charge", io::reals_of(s, [](const S& x) { return x.charge; })).header({});
  t.real("permittivity", "1", "relative permittivity", io::reals_of(s, [](const S& x) { return x.permittivity; }))
      .header({});
  t.real("force", "N", "electrostatic force (forces.csv fx, fy, fz)", xyz(sol.force, same))
      .over({"particle", "xyz"})
      .header({"fx", "fy", "fz"});
  t.real("torque", "N m", "electrostatic torque about the centre (forces.csv tx, ty, tz)", xyz(sol.torque, same))
      .over({"particle", "xyz"})
      .header({"tx", "ty", "tz"});
  return t;
}

void write_electrostatics(const OutputDir& out, const es::Solver& solver, const es::Problem& p,
                          const es::Solution& sol, bool surface) {
  io::write_csv(out, forces_table(p, sol));
  out.write_json("energy.json", nlohmann::json{{"energy_J", sol.energy}});
  out.write_json("stats.json", solve_stats(solver, p, sol));
  if (surface)
    out.write("surface.vtu", [&](std::ostream& os) { write_surface_vtu(os, solver.surface(), solver.surface_triangles()); });
}

io::Dataset electrostatics_dataset(const es::Solver& solver, const es::Problem& p, const es::Solution& sol) {
  io::Dataset d;
  forces_table(p, sol).add_to(d);
  d.add("energy", {}, "J", "electrostatic energy (energy.json energy_J)", {sol.energy});
  nlohmann::json stats = solve_stats(solver, p, sol);
  stats.erase("extra");
  io::add_scalars(d, stats);
  d.attributes["solver"] = solver.name();
  d.attributes["medium_permittivity"] = p.medium_permittivity;
  return d;
}

}  // namespace agglo::writers
