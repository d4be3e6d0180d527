#pragma once
// Twisting sub-model "marshall" (Marshall 2009; docs/model.md §A.2): a torsion spring about n,
//   k_Q = k_T a^2/2, k_T = 8 G* a [N m/rad],  eta_Q = eta_T a^2/2, eta_T = eta_N [N m s]
//   xi_Q += (w_i - w_j).n dt [rad],  M_Q = -k_Q xi_Q - eta_Q (w_i - w_j).n  [N m]
//   |M_Q| <= 2/3 a mu_F |F_ne + 2 F_C|  (spring reset at the limit)
// Returns the torque M_Q n on i; j receives the opposite.
#include <cmath>

#include "agglo/dem/contact/sub_model.hpp"

namespace agglo::dem::contact {

class MarshallTwisting {
 public:
  static constexpr Category category = Category::twisting;
  static constexpr const char* name = "marshall";
  static constexpr bool needs_sliding_spring = true;  // Marshall's springs go together

  explicit MarshallTwisting(const ContactParams& p);  // checks mu_F >= 0

  Vec3 torque(const ContactPoint& c, const JkrPair& jkr, ContactState& s) const {
    const double kt = 8.0 * gstar_ * c.a;
    const double kq = 0.5 * kt * c.a * c.a;
    const double eta_q = 0.5 * c.eta_n * c.a * c.a;
    const double limit_base = mu_ * std::abs(c.f_ne + 2.0 * jkr.Fc);
    const double wq = dot(c.w_rel, c.n);
    s.xi_q += wq * c.dt;
    double mq = -kq * s.xi_q - eta_q * wq;
    const double mlim = 2.0 / 3.0 * c.a * limit_base;
    if (std::abs(mq) > mlim) {
      mq = std::copysign(mlim, mq);
      s.xi_q = -(mq + eta_q * wq) / kq;
    }
    return mq * c.n;
  }

  // Lane form of torque (sub_model.hpp): the same operations, the limit as a select.
  static constexpr bool has_lanes = true;
  template <class T>
  [[gnu::always_inline]] lanes::V3<T> torque_lanes(const LanePoint<T>& c, T fc, T& xi_q) const {
    using namespace lanes;
    const T kt = 8.0 * gstar_ * c.a;
    const T kq = 0.5 * kt * c.a * c.a;
    const T eta_q = 0.5 * c.eta_n * c.a * c.a;
    const T limit_base = mu_ * abs(c.f_ne + 2.0 * fc);
    const T wq = dot(c.w_rel, c.n);
    xi_q = xi_q + wq * c.dt;
    const T mq_spring = -kq * xi_q - eta_q * wq;
    const T mlim = 2.0 / 3.0 * c.a * limit_base;
    const T mq_lim = copysign(mlim, mq_spring);
    const auto over = abs(mq_spring) > mlim;
    xi_q = select(over, -(mq_lim + eta_q * wq) / kq, xi_q);
    return select(over, mq_lim, mq_spring) * c.n;
  }

 private:
  double mu_, gstar_;
};

}  // namespace agglo::dem::contact
