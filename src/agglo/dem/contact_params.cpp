#include "agglo/dem/contact_params.hpp"

namespace agglo::dem {

double ContactParams::estar() const {
  if (pair_estar > 0.0) return pair_estar;
  return youngs_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
}

double ContactParams::value(const contact::Coefficient& c) const {
  const auto it = declared.find(c.key);
  return it == declared.end() ? c.def : it->second;
}

double ContactParams::gstar() const {
  if (pair_gstar > 0.0) return pair_gstar;
  double G = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  return G / (2.0 * (2.0 - poisson_ratio));
}

}  // namespace agglo::dem
