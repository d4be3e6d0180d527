#pragma once
// Normal sub-model "jkr": JKR adhesion with Marshall's hysteresis (docs/model.md §A.2; Marshall 2009,
// J. Comput. Phys. 228, 1541). The pair constants F_C, a0, delta_C are in JkrPair (jkr.hpp).
//   a(delta)  inverse of delta/delta_C = 6^(1/3) [2 (a/a0)^2 - 4/3 (a/a0)^(1/2)]   [m]
//   F_ne    = 4 F_C [(a/a0)^3 - (a/a0)^(3/2)]                                       [N], > 0 repulsive
//   k_N     = 4/3 E* a                                                              [N/m]
// A contact forms at delta >= 0 and breaks below -delta_C (break_rule "marshall") or at the force
// minimum -F_C, delta = -0.48075 delta_C (break_rule "lammps", LAMMPS' pair granular jkr).
#include "agglo/dem/contact/sub_model.hpp"

namespace agglo::dem::contact {

class JkrNormal {
 public:
  static constexpr Category category = Category::normal;
  static constexpr const char* name = "jkr";

  explicit JkrNormal(const ContactParams& p);  // checks E, nu and gamma

  // An active contact breaks when delta < -break_separation [m].
  double break_separation(const JkrPair& jkr) const {
    return rule_ == BreakRule::marshall ? jkr.deltaC : -kDeltaAtMinForce * jkr.deltaC;
  }
  // Contact radius for overlap delta; `a_prev` (0: none) is the last step's radius (warm start) [m].
  double contact_radius(const JkrPair& jkr, double delta, double a_prev) const { return jkr.a_of_delta(delta, a_prev); }
  // The fast path (jkr.hpp, jkr_root_fast): s = (a/a0)^(1/2) at overlap delta >= -delta_C, no warm start.
  static double contact_root(const JkrPair& jkr, double delta) { return jkr_root_fast(delta * jkr.t_per_delta); }
  // F_ne from s (the same formula as force(jkr, s^2 a0)) [N].
  static double force_of_root(const JkrPair& jkr, double s) { return jkr_force_of_root(jkr, s); }
  double force(const JkrPair& jkr, double a) const { return jkr.force_of_a(a); }
  double stiffness(const JkrPair& jkr, double a) const { return jkr.stiffness(a); }

 private:
  BreakRule rule_;
};

}  // namespace agglo::dem::contact
