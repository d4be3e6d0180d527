#pragma once
// Materials per particle (docs/model.md §A.2, "Materials"). Every particle carries a material id:
// 0 is the case's default material (the [material] values in ContactParams), k >= 1 the named
// material DemParams::materials[k - 1]. The contact law of a pair of materials a, b takes the
// following values (SI units):
//   1/E* = (1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b            effective modulus [Pa] (Johnson 1985, §4.2)
//   1/G* = (2 - nu_a)/G_a + (2 - nu_b)/G_b, G = E/(2(1 + nu))   tangential modulus [Pa] (Mindlin 1949)
//   gamma_ab = sqrt(gamma_a gamma_b)                      surface energy [J/m^2]: work of adhesion
//                                                         w_ab = 2 sqrt(gamma_a gamma_b), the geometric-
//                                                         mean (Berthelot) rule of dispersion forces
//                                                         (Israelachvili, Intermolecular and Surface
//                                                         Forces, 3rd ed., §17.4), so F_C = 3/2 pi w R*
//   e_ab = sqrt(e_a e_b)                                  restitution, geometric mean [-]
//   mu_ab = min(mu_a, mu_b)                               friction: the more slippery surface decides [-]
// R* = r_a r_b/(r_a + r_b) and m* = m_a m_b/(m_a + m_b) as for any pair. Two particles of one
// material use that material's own values (E* = E/(2(1 - nu^2)) etc.), bit for bit as with a single
// material. The rolling angle, the break rule and the declared model coefficients belong to [contact]
// and are shared by all materials.
#include <cstdint>
#include <string>
#include <vector>

#include "agglo/dem/contact_params.hpp"

namespace agglo::dem {

struct Material {
  std::string name;
  double density = 2500.0;         // rho [kg/m^3]
  double youngs_modulus = 1.0e9;   // E [Pa]
  double poisson_ratio = 0.33;     // nu [-]
  double surface_energy = 0.01;    // gamma [J/m^2]
  double restitution = 0.7;        // e [-]
  double friction = 0.3;           // mu_F [-]
};

// The contact settings of material `m` alone: `base` ([contact] options) with m's values.
ContactParams with_material(const ContactParams& base, const Material& m);
// The material the contact values of `c` describe (the default material, id 0), named `name`.
Material material_of(const ContactParams& c, double density, std::string name);

// The contact settings of a pair of materials a, b by the rules above (pair_estar/pair_gstar set
// when a and b differ).
ContactParams pair_contact(const ContactParams& base, const Material& a, const Material& b);

// The pair values of every ordered pair of material ids: entry a * count + b, count = 1 + named.size()
// (id 0 = the values of `base`). Symmetric: entry (a, b) equals entry (b, a).
struct MaterialPairs {
  std::size_t count = 1;
  std::vector<ContactParams> table;  // count * count entries

  MaterialPairs() = default;
  MaterialPairs(const ContactParams& base, const std::vector<Material>& named);
  std::uint32_t kind(std::uint32_t a, std::uint32_t b) const { return static_cast<std::uint32_t>(a * count + b); }
  const ContactParams& at(std::uint32_t a, std::uint32_t b) const { return table[kind(a, b)]; }
};

}  // namespace agglo::dem
