#include "agglo/impact/agglomerate.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/dem/jkr.hpp"
#include "agglo/impact/orientation.hpp"
#include "agglo/impact/structure_target.hpp"

namespace agglo::impact {

dem::Particles build_agglomerate(const ImpactCase& c) {
  const auto& a = c.agglomerate;
  dem::Particles p;
  if (a.shape == "list") {
    for (const auto& lp : a.particles) p.add(lp.position, lp.radius, a.density, {}, lp.charge, lp.permittivity);
    return p;
  }
  if (is_structure_shape(a.shape)) {
    place_structure(a, c.dem.contact, p);
    return p;
  }
  const double r = a.radius;
  auto jkr = dem::JkrPair::make(0.5 * r, c.dem.contact.estar(), c.dem.contact.surface_energy);
  const double L = 2.0 * r - jkr.delta_equilibrium();  // centre distance of touching neighbours
  const double q = a.charged ? a.charge_density * 4.0 * constants::pi * r * r : 0.0;
  std::vector<Vec3> pos;
  if (a.shape == "tetrahedron") {
    const double h = L / (2.0 * std::sqrt(2.0));
    pos = {{-h, 0.0, -L / 2}, {-h, 0.0, L / 2}, {h, -L / 2, 0.0}, {h, L / 2, 0.0}};
  } else {  // square, ring order 0 -> 1 -> 2 -> 3
    pos = {{-L / 2, -L / 2, 0.0}, {L / 2, -L / 2, 0.0}, {L / 2, L / 2, 0.0}, {-L / 2, L / 2, 0.0}};
  }
  if (const auto rot = named_orientation(a.shape, a.orientation))
    for (auto& x : pos) x = rot->apply(x);  // about the centroid, the origin
  const double sign[4] = {1.0, -1.0, 1.0, -1.0};
  for (int k = 0; k < 4; ++k) p.add(pos[k], r, a.density, {}, sign[k] * q, a.permittivity);
  return p;
}

void add_projectile(dem::Particles& p, const ImpactCase& c, double speed) {
  const auto& pj = c.projectile;
  Vec3 centroid;
  double xmin = 1e300, rref = c.agglomerate.radius;
  for (std::size_t k = 0; k < p.size(); ++k) {
    centroid += p.x[k] / static_cast<double>(p.size());
    xmin = std::min(xmin, p.x[k].x - p.r[k]);
  }
  Vec3 start{xmin - pj.gap_radii * rref - pj.radius, centroid.y + pj.offset_radii * rref, centroid.z};
  p.add(start, pj.radius, c.agglomerate.density, {speed, 0.0, 0.0}, pj.charge, pj.permittivity);
}

}  // namespace agglo::impact
