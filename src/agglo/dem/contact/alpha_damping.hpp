#pragma once
// Damping sub-model "alpha" (docs/model.md §A.2; Marshall 2009 after Tsuji et al. 1992):
//   eta_N = alpha(e) sqrt(m* k_N)   [kg/s],   F_nd = eta_N d(delta)/dt   [N]
// on every active contact (also in tension), m* = m_i m_j/(m_i + m_j), k_N from the normal model;
// the tangential and twisting models reuse eta_N. alpha(e) is a polynomial fit in the restitution
// coefficient e: alpha(1) ~ 0, increasing as e decreases.
#include <cmath>

#include "agglo/dem/contact/lanes.hpp"
#include "agglo/dem/contact/sub_model.hpp"

namespace agglo::dem::contact {

double damping_alpha(double restitution);

class AlphaDamping {
 public:
  static constexpr Category category = Category::damping;
  static constexpr const char* name = "alpha";

  explicit AlphaDamping(const ContactParams& p);  // checks e in (0, 1]

  // eta_N for reduced mass m* [kg] and normal stiffness k_N [N/m].
  double coefficient(double mstar, double k_n) const { return alpha_ * std::sqrt(mstar * k_n); }
  double alpha() const { return alpha_; }
  // Lane form (sub_model.hpp).
  static constexpr bool has_lanes = true;
  template <class T>
  [[gnu::always_inline]] T coefficient_lanes(T mstar, T k_n) const {
    return alpha_ * lanes::sqrt(mstar * k_n);
  }

 private:
  double alpha_;
};

}  // namespace agglo::dem::contact
