#include "agglo/dem/contact/jkr_normal.hpp"

namespace agglo::dem::contact {

JkrNormal::JkrNormal(const ContactParams& p) : rule_(p.break_rule) {
  require(p.youngs_modulus > 0.0, "normal", name, "Young's modulus E", p.youngs_modulus, "> 0 Pa");
  require(p.poisson_ratio > -1.0 && p.poisson_ratio < 0.5, "normal", name, "Poisson ratio nu",
          p.poisson_ratio, "in (-1, 0.5)");
  require(p.surface_energy > 0.0, "normal", name, "surface energy gamma", p.surface_energy, "> 0 J/m^2");
}

}  // namespace agglo::dem::contact
