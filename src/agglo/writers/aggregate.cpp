#include "agglo/writers/aggregate.hpp"

#include <algorithm>

#include "agglo/io/dataset_scalars.hpp"
#include "agglo/io/vtk.hpp"

namespace agglo::writers {

io::Table aggregate_table(const structure::Aggregate& a, const structure::Summary& s) {
  io::Table t("aggregate.csv", {{"primary", a.size()}}, "{:.17g}");
  t.real("x", "m", "primary centre x", io::reals_of(a.x, [](const Vec3& v) { return v.x; }));
  t.real("y", "m", "primary centre y", io::reals_of(a.x, [](const Vec3& v) { return v.y; }));
  t.real("z", "m", "primary centre z", io::reals_of(a.x, [](const Vec3& v) { return v.z; }));
  t.real("radius", "m", "primary radius", a.r);
  t.integer("coordination", "1", "contacts of the primary (|d - r_i - r_j| <= 1e-6 min r)",
            io::ints_of(s.contacts.coordination, [](int c) { return c; }));
  if (!a.charge.empty()) t.real("charge", "C", "free charge of the primary", a.charge);
  if (!a.permittivity.empty()) t.real("permittivity", "1", "relative permittivity of the primary", a.permittivity);
  if (!a.material.empty()) {  // codes in order of first appearance, the names as words
    std::vector<std::string> names;
    std::vector<std::int64_t> codes;
    for (const auto& m : a.material) {
      auto it = std::find(names.begin(), names.end(), m);
      if (it == names.end()) it = names.insert(names.end(), m);
      codes.push_back(it - names.begin());
    }
    t.flag("material", "material of the primary ([material] = default, or a [[materials]] name)", names, codes);
  }
  if (!a.density.empty()) t.real("density", "kg m-3", "density of the primary's material", a.density);
  return t;
}

nlohmann::json aggregate_json(const structure::Summary& s, const AggregateTarget& target) {
  nlohmann::json j = {{"shape", target.shape},
                      {"primaries", s.primaries},
                      {"radius_geometric_mean_m", s.abar},
                      {"rg_point_mass_m", s.rg_point_mass},
                      {"rg_spheres_m", s.rg_spheres},
                      {"contacts", s.contacts.pairs.size()},
                      {"max_contact_error", s.contacts.max_error},
                      {"mean_coordination", s.mean_coordination},
                      {"coordination_counts", s.coordination_counts}};
  j["target_fractal_dimension"] = target.fractal_dimension ? nlohmann::json(*target.fractal_dimension) : nullptr;
  j["target_fractal_prefactor"] = target.fractal_prefactor ? nlohmann::json(*target.fractal_prefactor) : nullptr;
  j["fitted_fractal_dimension"] = s.growth ? nlohmann::json(s.growth->fractal_dimension) : nullptr;
  j["fitted_fractal_dimension_stderr"] = s.growth ? nlohmann::json(s.growth->dimension_stderr) : nullptr;
  j["fitted_fractal_prefactor"] = s.growth ? nlohmann::json(s.growth->fractal_prefactor) : nullptr;
  return j;
}

void write_aggregate(const OutputDir& out, const structure::Aggregate& a, const structure::Summary& s,
                     const nlohmann::json& result) {
  io::write_csv(out, aggregate_table(a, s));
  std::vector<double> coordination(s.contacts.coordination.begin(), s.contacts.coordination.end());
  out.write("aggregate.vtp", [&](std::ostream& o) {
    io::write_vtp(o, a.x, {{"radius", "Float64", 1, a.r}, {"coordination", "Float64", 1, coordination}});
  });
  out.write_json("result.json", result);
}

io::Dataset aggregate_dataset(const structure::Aggregate& a, const structure::Summary& s, const nlohmann::json& result) {
  io::Dataset d;
  aggregate_table(a, s).add_to(d);
  io::add_scalars(d, result);  // the numbers of result.json; null (no fit) as NaN
  io::add_int_column(d, "coordination_counts", "coordination_number", "1",
                     "primaries with 0, 1, 2, ... contacts (result.json coordination_counts)",
                     io::ints_of(s.coordination_counts, [](int c) { return c; }));
  d.attributes["shape"] = result.at("shape").get<std::string>();
  return d;
}

}  // namespace agglo::writers
