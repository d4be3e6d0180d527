#pragma once
// Tangential sub-model "ruan_li": sliding friction of Ruan & Li (2022, eq. 2b), regularised near zero
// slip by a viscous branch (docs/model.md §A.2); contact.tangential = "seed" is its deprecated name:
//   F_t = -min(mu_F |F_n|, eta_t |v_s|) v_s/|v_s|,   eta_t = eta_N   [N]
// F_n includes the normal damping; no spring, no state, no torque of its own beyond the lever arm.
#include <algorithm>
#include <cmath>

#include "agglo/dem/contact/sub_model.hpp"

namespace agglo::dem::contact {

class RuanLiFriction {
 public:
  static constexpr Category category = Category::tangential;
  static constexpr const char* name = "ruan_li";

  explicit RuanLiFriction(const ContactParams& p);  // checks mu_F >= 0

  Vec3 force(const ContactPoint& c, const JkrPair&, ContactState&) const {
    Vec3 ft;
    const double vs_mag = norm(c.vs);
    if (vs_mag > 0.0) {
      const double mag = std::min(mu_ * std::abs(c.f_n), c.eta_n * vs_mag);
      ft = (-mag / vs_mag) * c.vs;
    }
    return ft;
  }

 private:
  double mu_;
};

}  // namespace agglo::dem::contact
