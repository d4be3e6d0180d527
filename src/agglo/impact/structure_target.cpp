#include "agglo/impact/structure_target.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "agglo/core/constants.hpp"
#include "agglo/dem/jkr.hpp"
#include "agglo/structure/ballistic.hpp"
#include "agglo/structure/csv_input.hpp"
#include "agglo/structure/fractal.hpp"
#include "agglo/structure/primaries.hpp"
#include "agglo/structure/validate.hpp"

namespace agglo::impact {

namespace {

// The key a BuildError names by its leaf (the shape when none matches).
const settings::Setting& key_of(const StructureKeys& ka, std::string_view leaf) {
  for (const settings::Setting* s : std::initializer_list<const settings::Setting*>{
           &ka.builder.primaries, &ka.builder.fractal_dimension, &ka.builder.fractal_prefactor,
           &ka.builder.radius_std, &ka.builder.file})
    if (s->leaf() == leaf) return *s;
  return ka.shape;
}

structure::Aggregate read_structure_file(const ConfigSection& ag, const std::string& case_file, AgglomerateSpec& a,
                                         const settings::BuilderKeys& ka) {
  if (!ka.file.present(ag)) ka.file.missing(ag, "shape = \"file\" needs the CSV file of the primaries");
  std::filesystem::path path = ka.file.read(ag);
  if (path.is_relative() && !case_file.empty()) path = std::filesystem::path(case_file).parent_path() / path;
  a.file = path.string();
  std::ifstream in(path);
  if (!in) ka.file.reject(ag, fmt::format("cannot open '{}'", a.file));
  return structure::read_aggregate_csv(in, a.file, "file");
}

structure::Aggregate generate(const ConfigSection& ag, AgglomerateSpec& a, const settings::BuilderKeys& ka) {
  a.primaries = static_cast<int>(ka.primaries.read(ag));
  a.radius_std = ka.radius_std.read(ag);
  a.seed = ka.seed.read(ag);
  if (a.shape == "fractal") {
    a.fractal_dimension = ka.fractal_dimension.read(ag);
    a.fractal_prefactor = ka.fractal_prefactor.read(ag);
  }
  return build_structure(a);
}

// Keys of the generated shapes set with a shape that does not read them.
void reject_unused_keys(const ConfigSection& ag, const AgglomerateSpec& a, const settings::BuilderKeys& ka) {
  const bool generated = a.shape == "fractal" || a.shape == "bpca" || a.shape == "bcca";
  for (const settings::Setting* s :
       std::initializer_list<const settings::Setting*>{&ka.primaries, &ka.radius_std, &ka.seed})
    if (!generated && s->present(ag)) s->reject(ag, "applies to shape = \"fractal\", \"bpca\" or \"bcca\" only");
  for (const settings::Setting* s :
       std::initializer_list<const settings::Setting*>{&ka.fractal_dimension, &ka.fractal_prefactor})
    if (a.shape != "fractal" && s->present(ag)) s->reject(ag, "applies to shape = \"fractal\" only");
  if (a.shape != "file" && ka.file.present(ag)) ka.file.reject(ag, "applies to shape = \"file\" only");
}

}  // namespace

structure::Aggregate build_structure(const AgglomerateSpec& a) {
  const auto seed = static_cast<std::uint64_t>(a.seed);
  if (a.shape == "fractal")
    return structure::build_fractal({a.primaries, a.fractal_dimension, a.fractal_prefactor, a.radius, a.radius_std, seed});
  const auto kind = a.shape == "bpca" ? structure::Ballistic::particle_cluster : structure::Ballistic::cluster_cluster;
  return structure::build_ballistic({kind, a.primaries, a.radius, a.radius_std, seed});
}

bool is_structure_shape(std::string_view shape) {
  return shape == "fractal" || shape == "bpca" || shape == "bcca" || shape == "file";
}

void parse_structure(const ConfigSection& ag, const std::string& case_file, AgglomerateSpec& a) {
  const auto& ka = impact_keys().agglomerate;
  parse_structure(ag, case_file, a, {ka.shape, ka.builder});
}

void parse_structure(const ConfigSection& ag, const std::string& case_file, AgglomerateSpec& a,
                     const StructureKeys& keys) {
  reject_unused_keys(ag, a, keys.builder);
  if (!is_structure_shape(a.shape)) return;
  try {
    a.structure = a.shape == "file" ? read_structure_file(ag, case_file, a, keys.builder) : generate(ag, a, keys.builder);
    (void)structure::validate_structure(a.structure, a.shape == "file" ? "file" : "shape");
  } catch (const structure::BuildError& e) {
    key_of(keys, e.key).reject(ag, e.what());
  }
}

void place_structure(const AgglomerateSpec& a, const ImpactCase& c, dem::Particles& p) {
  const auto& s = a.structure;
  const double abar = structure::geometric_mean(s.r);
  const dem::MaterialPairs mats(c.dem.contact, c.dem.materials);
  const auto& contact = mats.at(a.material_of(0), a.material_of(0));
  const auto jkr = dem::JkrPair::make(0.5 * abar, contact.estar(), contact.surface_energy);
  const double scale = 1.0 - jkr.delta_equilibrium() / (2.0 * abar);
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double r = s.r[k];
    double q = a.charged ? a.charge_density * 4.0 * constants::pi * r * r * (k % 2 == 0 ? 1.0 : -1.0) : 0.0;
    if (!s.charge.empty()) q = s.charge[k];
    const double kappa = s.permittivity.empty() ? a.permittivity : s.permittivity[k];
    const std::uint32_t mat = a.material_of(k);
    p.add(scale * s.x[k], r, material_density(c, mat), {}, q, kappa, mat);
  }
}

}  // namespace agglo::impact
