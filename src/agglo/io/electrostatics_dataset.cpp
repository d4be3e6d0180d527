#include "agglo/io/electrostatics_dataset.hpp"

#include "agglo/io/dataset_scalars.hpp"
#include "agglo/io/electrostatics_writers.hpp"

namespace agglo::io {

namespace {
std::vector<double> xyz(const std::vector<Vec3>& v) {
  std::vector<double> out;
  for (const auto& x : v) out.insert(out.end(), {x.x, x.y, x.z});
  return out;
}
}  // namespace

Dataset electrostatics_dataset(const es::Solver& solver, const es::Problem& p, const es::Solution& sol) {
  Dataset d;
  const auto& s = p.spheres;
  std::vector<std::int64_t> id;
  std::vector<double> radius, charge, permittivity;
  std::vector<Vec3> centre;
  for (std::size_t i = 0; i < s.size(); ++i) {
    id.push_back(static_cast<std::int64_t>(i));
    centre.push_back(s[i].center);
    radius.push_back(s[i].radius);
    charge.push_back(s[i].charge);
    permittivity.push_back(s[i].permittivity);
  }
  add_int_column(d, "particle", "particle", "1", "particle index (forces.csv id)", id);
  d.add_dim("xyz", 3);
  d.add("position", {"particle", "xyz"}, "m", "sphere centre", xyz(centre));
  d.add("radius", {"particle"}, "m", "electrostatic radius", radius);
  d.add("charge", {"particle"}, "C", "free charge", charge);
  d.add("permittivity", {"particle"}, "1", "relative permittivity", permittivity);
  d.add("force", {"particle", "xyz"}, "N", "electrostatic force (forces.csv fx, fy, fz)", xyz(sol.force));
  d.add("torque", {"particle", "xyz"}, "N m", "electrostatic torque about the centre (forces.csv tx, ty, tz)",
        xyz(sol.torque));
  d.add("energy", {}, "J", "electrostatic energy (energy.json energy_J)", {sol.energy});
  nlohmann::json stats = solve_stats(solver, p, sol);
  stats.erase("extra");
  add_scalars(d, stats);
  d.attributes["solver"] = solver.name();
  d.attributes["medium_permittivity"] = p.medium_permittivity;
  return d;
}

}  // namespace agglo::io
