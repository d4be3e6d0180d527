#pragma once
// Rolling sub-model "marshall" (Marshall 2009; docs/model.md §A.2): a rolling spring without damping,
//   k_R = 4 F_C (a/a0)^(3/2)  [N]
//   xi_R += R dt (w_i - w_j) x n  (kept in the tangent plane),  |xi_R| <= theta_crit R  [m]
//   M_R = -k_R n x xi_R  [N m]
// so the rolling moment is capped at k_R theta_crit R. Returns the torque on i; j receives the opposite.
#include <cmath>

#include "agglo/dem/contact/sub_model.hpp"
#include "agglo/dem/contact/tangent_plane.hpp"

namespace agglo::dem::contact {

class MarshallRolling {
 public:
  static constexpr Category category = Category::rolling;
  static constexpr const char* name = "marshall";
  static constexpr bool needs_sliding_spring = true;  // Marshall's springs go together

  explicit MarshallRolling(const ContactParams& p);  // checks theta_crit > 0

  Vec3 torque(const ContactPoint& c, const JkrPair& jkr, ContactState& s) const {
    const double x = c.a / jkr.a0;
    const double kr = 4.0 * jkr.Fc * x * std::sqrt(x);
    rotate_into_plane(s.xi_r, c.n);
    s.xi_r += (jkr.R * c.dt) * cross(c.w_rel, c.n);
    const double xi_crit = theta_crit_ * jkr.R;
    const double xr = norm(s.xi_r);
    if (xr > xi_crit) s.xi_r *= xi_crit / xr;
    return -kr * cross(c.n, s.xi_r);
  }

  // Lane form of torque (sub_model.hpp): the same operations, the cap as a select.
  static constexpr bool has_lanes = true;
  template <class T>
  [[gnu::always_inline]] lanes::V3<T> torque_lanes(const LanePoint<T>& c, T fc, T a0, T R, lanes::V3<T>& xi_r) const {
    using namespace lanes;
    const T x = c.a / a0;
    const T kr = 4.0 * fc * x * sqrt(x);
    xi_r = rotated_into_plane(xi_r, c.n) + (R * c.dt) * cross(c.w_rel, c.n);
    const T xi_crit = theta_crit_ * R;
    const T xr = norm(xi_r);
    xi_r = select(xr > xi_crit, xi_r * (xi_crit / xr), xi_r);
    return -kr * cross(c.n, xi_r);
  }

 private:
  double theta_crit_;
};

}  // namespace agglo::dem::contact
