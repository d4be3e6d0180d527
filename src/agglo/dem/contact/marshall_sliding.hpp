#pragma once
// Tangential sub-model "marshall": sliding spring with Coulomb limit (Marshall 2009, J. Comput.
// Phys. 228, 1541; docs/model.md §A.2):
//   k_T = 8 G* a [N/m],  eta_T = eta_N [kg/s],  xi_T += v_s dt (kept in the tangent plane) [m]
//   F_t = -k_T xi_T - eta_T v_s,  |F_t| <= mu_F |F_ne + 2 F_C|  [N]
// At the limit F_t is scaled back and the spring reset to the length that produces it.
#include "agglo/dem/contact/sub_model.hpp"
#include "agglo/dem/contact/tangent_plane.hpp"

namespace agglo::dem::contact {

class MarshallSliding {
 public:
  static constexpr Category category = Category::tangential;
  static constexpr const char* name = "marshall";
  static constexpr bool sliding_spring = true;

  explicit MarshallSliding(const ContactParams& p);  // checks mu_F >= 0

  Vec3 force(const ContactPoint& c, const JkrPair& jkr, ContactState& s) const {
    const double kt = 8.0 * gstar_ * c.a;
    const double eta_t = c.eta_n;
    const double flim = mu_ * std::abs(c.f_ne + 2.0 * jkr.Fc);
    rotate_into_plane(s.xi_t, c.n);
    s.xi_t += c.vs * c.dt;
    Vec3 ft = -kt * s.xi_t - eta_t * c.vs;
    const double fmag = norm(ft);
    if (fmag > flim) {
      ft *= flim / fmag;
      s.xi_t = -(ft + eta_t * c.vs) / kt;
    }
    return ft;
  }

  // Lane form of force (sub_model.hpp): the same operations, the limit as a select.
  static constexpr bool has_lanes = true;
  template <class T>
  [[gnu::always_inline]] lanes::V3<T> force_lanes(const LanePoint<T>& c, T fc, lanes::V3<T>& xi_t) const {
    using namespace lanes;
    const T kt = 8.0 * gstar_ * c.a;
    const T eta_t = c.eta_n;
    const T flim = mu_ * abs(c.f_ne + 2.0 * fc);
    xi_t = rotated_into_plane(xi_t, c.n) + c.vs * c.dt;
    const V3<T> ft = -kt * xi_t - eta_t * c.vs;
    const T fmag = norm(ft);
    const V3<T> ft_lim = ft * (flim / fmag);
    const auto over = fmag > flim;
    xi_t = select(over, -(ft_lim + eta_t * c.vs) / kt, xi_t);
    return select(over, ft_lim, ft);
  }

 private:
  double mu_, gstar_;
};

}  // namespace agglo::dem::contact
