#include "agglo/dem/wall.hpp"

namespace agglo::dem {

std::string_view wall_material_name(WallMaterial m) {
  switch (m) {
    case WallMaterial::same: return "same";
    case WallMaterial::rigid: return "rigid";
    case WallMaterial::named: break;
  }
  return "named";
}

double wall_estar(WallMaterial m, double youngs_modulus, double poisson_ratio) {
  const double plane = youngs_modulus / (1.0 - poisson_ratio * poisson_ratio);  // E/(1 - nu^2) of one body
  return m == WallMaterial::same ? 0.5 * plane : plane;
}

std::uint32_t wall_kind(const Wall& w, const MaterialPairs& mats, std::uint32_t mat) {
  return mats.kind(mat, w.material == WallMaterial::named ? w.material_id : mat);
}

JkrPair wall_jkr(const Wall& w, const MaterialPairs& mats, std::uint32_t mat, double r) {
  const ContactParams& c = mats.table[wall_kind(w, mats, mat)];
  if (w.material == WallMaterial::named) return JkrPair::make(r, c.estar(), c.surface_energy);
  return JkrPair::make(r, wall_estar(w.material, c.youngs_modulus, c.poisson_ratio), c.surface_energy);
}

}  // namespace agglo::dem
