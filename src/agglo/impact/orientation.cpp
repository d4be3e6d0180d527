#include "agglo/impact/orientation.hpp"

#include <cmath>
#include <stdexcept>

#include "agglo/core/constants.hpp"

namespace agglo::impact {

std::string original_orientation(std::string_view shape) {
  if (shape == "tetrahedron") return "edge_across";
  if (shape == "square") return "edge_along";
  return "";
}

std::optional<Rotation> named_orientation(std::string_view shape, std::string_view orientation) {
  if (orientation.empty() || orientation == original_orientation(shape)) return std::nullopt;
  const Vec3 ex{1.0, 0.0, 0.0}, ey{0.0, 1.0, 0.0}, ez{0.0, 0.0, 1.0};
  const double half_pi = 0.5 * constants::pi;
  const double apex = std::atan(std::sqrt(2.0));  // angle about z from +x (midpoint of edge 2-3) to vertex 3
  if (shape == "tetrahedron") {
    if (orientation == "edge_along") return rotation_about(ex, half_pi);
    if (orientation == "face") return rotation_about(ez, -apex);
    if (orientation == "vertex") return rotation_about(ez, constants::pi - apex);
  } else if (shape == "square") {
    if (orientation == "edge_across") return rotation_about(ex, half_pi);
    if (orientation == "face") return rotation_about(ey, half_pi);
    if (orientation == "vertex") return rotation_about(ez, -0.5 * half_pi);
  }
  throw std::invalid_argument("unknown orientation '" + std::string(orientation) + "' of shape '" +
                              std::string(shape) + "'");
}

void rotate_about_centroid(dem::Particles& p, const Rotation& r, std::size_t n) {
  if (n == 0) n = p.size();
  Vec3 c;
  for (std::size_t k = 0; k < n; ++k) c += p.x[k] / static_cast<double>(n);
  for (std::size_t k = 0; k < n; ++k) {
    p.x[k] = c + r.apply(p.x[k] - c);
    p.v[k] = r.apply(p.v[k]);
    p.w[k] = r.apply(p.w[k]);
  }
}

}  // namespace agglo::impact
