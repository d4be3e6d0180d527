#include "agglo/dem/wall.hpp"

namespace agglo::dem {

std::string_view wall_material_name(WallMaterial m) { return m == WallMaterial::same ? "same" : "rigid"; }

double wall_estar(WallMaterial m, double youngs_modulus, double poisson_ratio) {
  const double plane = youngs_modulus / (1.0 - poisson_ratio * poisson_ratio);  // E/(1 - nu^2) of one body
  return m == WallMaterial::same ? 0.5 * plane : plane;
}

}  // namespace agglo::dem
