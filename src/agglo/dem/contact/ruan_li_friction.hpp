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

  // Lane form of force (sub_model.hpp): the same operations, the branch as a select.
  static constexpr bool has_lanes = true;
  template <class T>
  [[gnu::always_inline]] lanes::V3<T> force_lanes(const LanePoint<T>& c, T, lanes::V3<T>&) const {
    using namespace lanes;
    const T vs_mag = norm(c.vs);
    const T mag = minimum(mu_ * abs(c.f_n), c.eta_n * vs_mag);
    const V3<T> zero{T{}, T{}, T{}};
    return select(vs_mag > 0.0, (-mag / vs_mag) * c.vs, zero);
  }

 private:
  double mu_;
};

}  // namespace agglo::dem::contact
