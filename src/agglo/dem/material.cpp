#include "agglo/dem/material.hpp"

#include <algorithm>
#include <cmath>

namespace agglo::dem {

ContactParams with_material(const ContactParams& base, const Material& m) {
  ContactParams c = base;
  c.youngs_modulus = m.youngs_modulus;
  c.poisson_ratio = m.poisson_ratio;
  c.surface_energy = m.surface_energy;
  c.restitution = m.restitution;
  c.friction = m.friction;
  c.pair_estar = c.pair_gstar = 0.0;
  return c;
}

Material material_of(const ContactParams& c, double density, std::string name) {
  return Material{std::move(name), density,        c.youngs_modulus, c.poisson_ratio,
                  c.surface_energy, c.restitution, c.friction};
}

ContactParams pair_contact(const ContactParams& base, const Material& a, const Material& b) {
  ContactParams c = with_material(base, a);
  const bool alike = a.youngs_modulus == b.youngs_modulus && a.poisson_ratio == b.poisson_ratio &&
                     a.surface_energy == b.surface_energy && a.restitution == b.restitution &&
                     a.friction == b.friction;
  if (alike) return c;
  auto shear = [](const Material& m) { return m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio)); };
  c.pair_estar = 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                        (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
  c.pair_gstar = 1.0 / ((2.0 - a.poisson_ratio) / shear(a) + (2.0 - b.poisson_ratio) / shear(b));
  c.surface_energy = std::sqrt(a.surface_energy * b.surface_energy);
  c.restitution = std::sqrt(a.restitution * b.restitution);
  c.friction = std::min(a.friction, b.friction);
  return c;
}

MaterialPairs::MaterialPairs(const ContactParams& base, const std::vector<Material>& named)
    : count(1 + named.size()) {
  std::vector<Material> all{material_of(base, 0.0, "")};
  all.insert(all.end(), named.begin(), named.end());
  table.reserve(count * count);
  for (const auto& a : all)
    for (const auto& b : all) table.push_back(pair_contact(base, a, b));
}

}  // namespace agglo::dem
