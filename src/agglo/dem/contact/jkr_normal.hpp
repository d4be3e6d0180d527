#pragma once
// Normal sub-model "jkr": JKR adhesion with Marshall's hysteresis (docs/model.md §A.2; Marshall 2009,
// J. Comput. Phys. 228, 1541). The pair constants F_C, a0, delta_C are in JkrPair (jkr.hpp).
//   a(delta)  inverse of delta/delta_C = 6^(1/3) [2 (a/a0)^2 - 4/3 (a/a0)^(1/2)]   [m]
//   F_ne    = 4 F_C [(a/a0)^3 - (a/a0)^(3/2)]                                       [N], > 0 repulsive
//   k_N     = 4/3 E* a                                                              [N/m]
// A contact forms at delta >= 0 and breaks below -delta_C (break_rule "marshall") or at the force
// minimum -F_C, delta = -0.48075 delta_C (break_rule "lammps", LAMMPS' pair granular jkr).
#include <cstdint>
#include <utility>

#include "agglo/dem/contact/lanes.hpp"
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

  // Lane forms (sub_model.hpp) of force_of_root and stiffness, F_C and E* per lane: the same expressions.
  static constexpr bool has_lanes = true;
  // contact_root on T = delta t_per_delta: jkr_root_fast itself for a double; for a Lane the same operations
  // with the table's coefficients gathered per lane (every lane through jkr_root_fast if one is beyond the table).
  template <class T>
  [[gnu::always_inline]] static T contact_root_lanes(T t) {
    if constexpr (sizeof(T) == sizeof(double)) {
      return jkr_root_fast(t);
    } else {
      using namespace lanes;
      constexpr int W = kWidth<T>;
      const T x = sqrt(maximum(t + kJkrSMin, T{})) * (kJkrTableCells / kJkrTableW);
      bool in_table = true;
      for (int l = 0; l < W; ++l) in_table = in_table && x[l] < kJkrTableCells;
      if (!in_table) [[unlikely]] {
        T s;
        for (int l = 0; l < W; ++l) s[l] = jkr_root_fast(t[l]);
        return s;
      }
      const Cells<W> cell = __builtin_convertvector(x, Cells<W>);
      const T u = x - __builtin_convertvector(cell, T);
      const auto& tab = kJkrRootTable.c;
      const auto coefficient = [&]<std::size_t... L>(int e, std::index_sequence<L...>) {
        return T{tab[cell[L]][e]...};
      };
      constexpr auto all = std::make_index_sequence<W>{};
      const T c0 = coefficient(0, all), c1 = coefficient(1, all), c2 = coefficient(2, all), c3 = coefficient(3, all);
      const T s = c0 + u * (c1 + u * (c2 + u * c3));
      const T s3 = s * s * s;
      const T g = 2.0 * s3 * s - 4.0 / 3.0 * s - t;
      const T gp = 8.0 * s3 - 4.0 / 3.0;
      const T den = 2.0 * gp * gp - g * (24.0 * s * s);
      const T step = select(den != 0.0, 2.0 * g * gp / den, T{});
      return maximum(s - step, T{} + kJkrSMin);
    }
  }
  template <class T>
  [[gnu::always_inline]] static T force_of_root_lanes(T fc, T s) {
    const T s3 = s * s * s;
    return 4.0 * fc * s3 * (s3 - 1.0);
  }
  template <class T>
  [[gnu::always_inline]] static T stiffness_lanes(T estar, T a) {
    return 4.0 / 3.0 * estar * a;
  }

 private:
  BreakRule rule_;
};

}  // namespace agglo::dem::contact
