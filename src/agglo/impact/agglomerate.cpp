#include "agglo/impact/agglomerate.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/dem/jkr.hpp"
#include "agglo/impact/orientation.hpp"
#include "agglo/impact/structure_target.hpp"
#include "agglo/structure/geometry.hpp"

namespace agglo::impact {

dem::Particles build_agglomerate(const ImpactCase& c) {
  const auto& a = c.agglomerate;
  dem::Particles p;
  if (a.shape == "list") {
    for (std::size_t k = 0; k < a.particles.size(); ++k) {
      const auto& lp = a.particles[k];
      const std::uint32_t mat = a.material_of(k);
      p.add(lp.position, lp.radius, material_density(c, mat), {}, lp.charge, lp.permittivity, mat);
    }
    return p;
  }
  if (is_structure_shape(a.shape)) {
    place_structure(a, c, p);
    return p;
  }
  const double r = a.radius;
  const dem::MaterialPairs mats(c.dem.contact, c.dem.materials);
  const auto& cp = mats.at(a.material, a.material);
  auto jkr = dem::JkrPair::make(0.5 * r, cp.estar(), cp.surface_energy);
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
  for (int k = 0; k < 4; ++k)
    p.add(pos[k], r, material_density(c, a.material), {}, sign[k] * q, a.permittivity, a.material);
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
  if (pj.shape == "sphere") {
    Vec3 start{xmin - pj.gap_radii * rref - pj.radius, centroid.y + pj.offset_radii * rref, centroid.z};
    p.add(start, pj.radius, material_density(c, pj.material), {speed, 0.0, 0.0}, pj.charge, pj.permittivity,
          pj.material);
    return;
  }
  dem::Particles body;  // centroid at the origin
  place_structure(pj.body, c, body);
  double xmax = -1e300;
  for (std::size_t k = 0; k < body.size(); ++k) {
    body.x[k] = pj.rotation.apply(body.x[k]);
    xmax = std::max(xmax, body.x[k].x + body.r[k]);
  }
  const Vec3 shift{xmin - pj.gap_radii * rref - xmax, centroid.y + pj.offset_radii * rref, centroid.z};
  for (std::size_t k = 0; k < body.size(); ++k)
    p.add(body.x[k] + shift, body.r[k], material_density(c, body.mat[k]), {speed, 0.0, 0.0}, body.q[k],
          body.kappa[k], body.mat[k]);
}

Rotation projectile_orientation(const ImpactCase& c, int k) {
  constexpr std::uint64_t kOrientationStream = 0x70726f6aULL;  // "proj": apart from the builder's streams
  CounterRng rng(static_cast<std::uint64_t>(c.projectile.body.seed), kOrientationStream, static_cast<std::uint64_t>(k));
  return structure::random_rotation(rng);
}

}  // namespace agglo::impact
