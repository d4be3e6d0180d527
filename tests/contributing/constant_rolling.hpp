#pragma once
// Rolling sub-model "constant": a moment of fixed size opposing the relative rolling,
//   M_R = -mu_R R |F_ne + 2 F_C| w_R/|w_R|,  w_R = (w_i - w_j) - ((w_i - w_j).n) n   [N m]
// (type A rolling resistance; docs/model.md §A.2 for F_ne, F_C). Returns the moment on i.
#include <cmath>

#include "agglo/dem/contact/sub_model.hpp"

namespace agglo::dem::contact {

class ConstantRolling {
 public:
  static constexpr Category category = Category::rolling;
  static constexpr const char* name = "constant";
  static constexpr Coefficient coefficients[] = {
      {"contact.rolling_friction", "", "rolling friction coefficient mu_R of the constant rolling model", 0.0, 0.0,
       1.0}};

  explicit ConstantRolling(const ContactParams& p) : mu_r_(p.value(coefficients[0])) {}

  Vec3 torque(const ContactPoint& c, const JkrPair& jkr, ContactState&) const {
    const Vec3 w = c.w_rel - dot(c.w_rel, c.n) * c.n;
    const double len = norm(w);
    if (len == 0.0) return {};
    return (-mu_r_ * jkr.R * std::abs(c.f_ne + 2.0 * jkr.Fc) / len) * w;
  }

 private:
  double mu_r_;
};

}  // namespace agglo::dem::contact
