#pragma once
// The pair loop compiled for one combination of sub-models (docs/model.md §A.2). Per pair:
//   1. overlap delta = r_i + r_j - |x_j - x_i|; hysteresis: a contact forms at delta >= 0 and breaks
//      below -Normal::break_separation (state reset on both events);
//   2. a = Normal::contact_radius, F_ne = Normal::force, eta_N = Damping::coefficient(m*, k_N);
//   3. relative velocity at the contact plane with levers l_i + l_j = |x_j - x_i| (l_i = r_i at
//      touching, conserving angular momentum exactly); F_n = F_ne + eta_N d(delta)/dt on i along -n;
//   4. F_t = Tangential::force, then Twisting::torque and Rolling::torque (moments on i, -moment on j;
//      models declaring `inactive` are skipped), finally the lever torques l_i n x F_t, l_j n x F_t.
// The interface each sub-model implements is the call made on it below.
#include <cstdint>

#include "agglo/dem/contact/contact_kernel.hpp"
#include "agglo/dem/contact/contact_point.hpp"
#include "agglo/dem/contact/model_names.hpp"
#include "agglo/dem/contact_params.hpp"
#include "agglo/dem/parallel_for.hpp"

namespace agglo::dem::contact {

template <class M>
concept Inactive = requires { requires M::inactive; };

template <class Normal, class Damping, class Tangential, class Rolling, class Twisting>
class PairKernel final : public ContactKernel {
  static_assert(Normal::category == Category::normal && Damping::category == Category::damping &&
                Tangential::category == Category::tangential && Rolling::category == Category::rolling &&
                Twisting::category == Category::twisting);

 public:
  explicit PairKernel(const ContactParams& p)
      : normal_(p), damping_(p), tangential_(p), rolling_(p), twisting_(p) {}

  void evaluate_pairs(std::vector<Pair>& pairs, const Particles& p, double dt,
                      std::vector<PairForce>& out) const override {
    out.resize(pairs.size());
    parallel_for(static_cast<std::int64_t>(pairs.size()), [&](std::int64_t k) {
      Pair& pr = pairs[k];
      const PairKinematics kin{p.x[pr.i], p.x[pr.j], p.v[pr.i], p.v[pr.j], p.w[pr.i], p.w[pr.j],
                               p.r[pr.i], p.r[pr.j], p.m[pr.i], p.m[pr.j]};
      out[k] = force(pr.jkr, kin, pr.state, dt);
    });
  }

  PairForce evaluate_pair(const JkrPair& jkr, const PairKinematics& k, ContactState& s,
                          double dt) const override {
    return force(jkr, k, s, dt);
  }

 private:
  // Step 1: true while the contact is (or becomes) active.
  bool engaged(const JkrPair& jkr, double delta, ContactState& s) const {
    s.delta = delta;
    if (!s.active) {
      if (delta < 0.0) return false;
      s = ContactState{};
      s.active = true;
      s.delta = delta;
    } else if (delta < -normal_.break_separation(jkr)) {
      s = ContactState{};
      s.delta = delta;
      return false;
    }
    return true;
  }

  // flatten: the sub-model calls are inlined into one body (as fast as a hand-written law; without it
  // GCC keeps them out of line and a step costs ~25 % more).
  [[gnu::flatten]] PairForce force(const JkrPair& jkr, const PairKinematics& k, ContactState& s, double dt) const {
    PairForce out;
    const Vec3 d = k.xj - k.xi;
    const double dist = norm(d);
    const double delta = k.ri + k.rj - dist;
    if (!engaged(jkr, delta, s)) return out;
    ContactPoint c;
    c.n = d / dist;  // from i to j
    s.a = normal_.contact_radius(jkr, delta, s.a);
    c.a = s.a;
    c.f_ne = normal_.force(jkr, c.a);
    const double mstar = k.mi * k.mj / (k.mi + k.mj);
    c.eta_n = damping_.coefficient(mstar, normal_.stiffness(jkr, c.a));
    const double li = (dist * dist + k.ri * k.ri - k.rj * k.rj) / (2.0 * dist);
    const double lj = dist - li;
    const Vec3 vrel = k.vi - k.vj + cross(li * k.wi + lj * k.wj, c.n);
    const double ddelta_dt = dot(vrel, c.n);
    c.vs = vrel - ddelta_dt * c.n;
    c.f_n = c.f_ne + c.eta_n * ddelta_dt;  // > 0 repulsive
    c.w_rel = k.wi - k.wj;
    c.dt = dt;
    out.f_on_i = -c.f_n * c.n;
    const Vec3 ft = tangential_.force(c, jkr, s);
    add_moment(twisting_, c, jkr, s, out);
    add_moment(rolling_, c, jkr, s, out);
    out.f_on_i += ft;
    out.t_on_i += li * cross(c.n, ft);
    out.t_on_j += lj * cross(c.n, ft);
    return out;
  }

  template <class Resistance>
  static void add_moment(const Resistance& model, const ContactPoint& c, const JkrPair& jkr, ContactState& s,
                         PairForce& out) {
    if constexpr (!Inactive<Resistance>) {
      const Vec3 m = model.torque(c, jkr, s);
      out.t_on_i += m;
      out.t_on_j -= m;
    }
  }

  Normal normal_;
  Damping damping_;
  Tangential tangential_;
  Rolling rolling_;
  Twisting twisting_;
};

}  // namespace agglo::dem::contact
