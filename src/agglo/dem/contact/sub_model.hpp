#pragma once
// What a contact sub-model includes and implements. Every sub-model is a small class with
//   static constexpr Category category;          static constexpr const char* name;
//   explicit Model(const ContactParams& p);       // copies and checks its coefficients (require())
// and the per-pair method of its category, called by pair_kernel.hpp for each active contact:
//   normal      double break_separation(const JkrPair&) const;   [m] breaks when delta < -this
//               double contact_radius(const JkrPair&, double delta, double a_prev) const;   [m]
//               double force(const JkrPair&, double a) const;     [N] elastic, > 0 repulsive
//               double stiffness(const JkrPair&, double a) const; [N/m] k_N for the damping
//   damping     double coefficient(double mstar, double k_n) const;                [kg/s] eta_N
//   tangential  Vec3 force(const ContactPoint&, const JkrPair&, ContactState&) const;   [N] on i
//   rolling,    Vec3 torque(const ContactPoint&, const JkrPair&, ContactState&) const; [N m] on i
//   twisting    (j receives the opposite), or `static constexpr bool inactive = true;` to do nothing.
// A model may also give the fast path a lane form (lanes.hpp; the same operations on T = double or a Lane
// of pairs, branches as selects), declared by `static constexpr bool has_lanes = true;`; the pair loop runs
// several pairs at once when all five models have one (inactive rolling and twisting count as having one):
//   normal      template <class T> static T force_of_root_lanes(T fc, T s);  static T stiffness_lanes(T estar, T a);
//   damping     template <class T> T coefficient_lanes(T mstar, T k_n) const;
//   tangential  template <class T> lanes::V3<T> force_lanes(const LanePoint<T>&, T fc, lanes::V3<T>& xi_t) const;
//   rolling     template <class T> lanes::V3<T> torque_lanes(const LanePoint<T>&, T fc, T a0, T R, lanes::V3<T>& xi_r) const;
//   twisting    template <class T> lanes::V3<T> torque_lanes(const LanePoint<T>&, T fc, T& xi_q) const;
// A model with coefficients of its own declares their [contact] keys (unit, default, range, meaning):
//   static constexpr Coefficient coefficients[] = {...};   read with p.value(coefficients[k])
// (coefficient.hpp); the settings table, the case parser and docs/config.md take them from there.
// Springs keep their displacement in ContactState (xi_t, xi_r, xi_q), reset when a contact forms.
// Compatibility is declared by the models themselves (as LAMMPS' granular sub-models declare
// allow_cohesion), and checked by the registry when a combination is chosen:
//   tangential  static constexpr bool sliding_spring = true;        it keeps a sliding spring xi_t
//   rolling,    static constexpr bool needs_sliding_spring = true;  only with such a tangential model
//   twisting
#include "agglo/core/vec3.hpp"
#include "agglo/dem/contact/coefficient_check.hpp"
#include "agglo/dem/contact/contact_point.hpp"
#include "agglo/dem/contact/model_names.hpp"
#include "agglo/dem/contact/pair_state.hpp"
#include "agglo/dem/contact_params.hpp"
#include "agglo/dem/jkr.hpp"
