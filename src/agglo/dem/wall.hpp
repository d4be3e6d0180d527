#pragma once
// A flat wall for the DEM (docs/model.md §A.5): the plane through `point` with unit `normal`, pointing
// to the side where the particles are. A sphere of radius r at centre x has the signed centre height
// h = (x - point) . normal and the overlap delta = r - h with the wall; the contact is the JKR pair law
// of docs/model.md §A.2 in the limit of a partner of infinite radius and mass, evaluated by the same
// sub-models as a sphere pair (contact/pair_kernel.hpp):
//   R*  = r                                  effective radius [m]
//   m*  = m                                  effective mass (damping eta_N = alpha(e) sqrt(m k_N)) [kg]
//   E*  = E / (2 (1 - nu^2))                 material "same": the wall is made of the particles' material
//   E*  = E / (1 - nu^2)                     material "rigid": the wall does not deform
//   gamma: the particles' surface energy (work of adhesion 2 gamma), so F_C = 3 pi gamma r
//   material "named" (a material of its own, material.hpp): E*, gamma, e and mu of the pair of the
//   particle's material and the wall's by the pair rules of material.hpp (E* = 1/((1 - nu_p^2)/E_p +
//   (1 - nu_w^2)/E_w), gamma = sqrt(gamma_p gamma_w)); "same" and "rigid" take e and mu of the particle
//   normal n = -normal (from the sphere to the wall), lever to the contact plane l = h (l = r at touch),
//   relative velocity at the contact v + l w x n (the wall is at rest and does not rotate).
// With these, the wall's pull-off force is twice a like pair's and its undamped sticking velocity
// 1.3679 sqrt(F_C delta_C / m) is 2^(1/6) times the head-on pair's (same material) or 2^(-1/6)
// times it (rigid wall).
#include <cstdint>
#include <string_view>
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/dem/contact/pair_state.hpp"
#include "agglo/dem/jkr.hpp"
#include "agglo/dem/material.hpp"

namespace agglo::dem {

enum class WallMaterial { same, rigid, named };

struct Wall {
  Vec3 point;                                 // a point of the plane [m]
  Vec3 normal{1.0, 0.0, 0.0};                 // unit normal, towards the particles
  WallMaterial material = WallMaterial::same;
  std::uint32_t material_id = 0;              // material named: its id (material.hpp)

  // Signed distance of x from the plane, positive on the particles' side [m].
  double height(const Vec3& x) const { return dot(x - point, normal); }
};

std::string_view wall_material_name(WallMaterial m);

// Effective modulus E* of a sphere of modulus E and Poisson ratio nu against the wall [Pa]
// (material same or rigid).
double wall_estar(WallMaterial m, double youngs_modulus, double poisson_ratio);

// The material pair (MaterialPairs::kind) and JKR constants of a sphere of radius r [m] and material
// id `mat` against wall `w`.
std::uint32_t wall_kind(const Wall& w, const MaterialPairs& mats, std::uint32_t mat);
JkrPair wall_jkr(const Wall& w, const MaterialPairs& mats, std::uint32_t mat, double r);

// The kinematics of one sphere as the wall contact sees it.
struct WallKinematics {
  double h = 0.0;   // centre height above the wall [m]
  Vec3 n;           // unit normal from the sphere to the wall (-Wall::normal)
  Vec3 v, w;        // velocity [m/s] and angular velocity [rad/s] of the sphere
  double r = 0.0, m = 0.0;  // radius [m], mass [kg]
};

// Contact states of every particle with one wall, their JKR constants (R* = r) and material pairs
// (MaterialPairs::kind of the particle's material and the wall's; material.hpp).
struct WallContacts {
  std::vector<ContactState> state;
  std::vector<JkrPair> jkr;
  std::vector<std::uint32_t> kind;
};

}  // namespace agglo::dem
