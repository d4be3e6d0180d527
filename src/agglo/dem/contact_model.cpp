#include "agglo/dem/contact_model.hpp"

#include <algorithm>
#include <cmath>

namespace agglo::dem {

double ContactParams::estar() const { return youngs_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio)); }

double ContactParams::gstar() const {
  double G = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  return G / (2.0 * (2.0 - poisson_ratio));
}

double break_separation(const ContactParams& p, const JkrPair& jkr) {
  return p.break_rule == BreakRule::marshall ? jkr.deltaC : -kDeltaAtMinForce * jkr.deltaC;
}

namespace {
// Keep a spring vector in the tangent plane of n, preserving its length.
inline void rotate_into_plane(Vec3& xi, const Vec3& n) {
  double len2 = norm2(xi);
  if (len2 == 0.0) return;
  xi -= dot(xi, n) * n;
  double l2 = norm2(xi);
  if (l2 > 0.0) xi *= std::sqrt(len2 / l2);
}
}  // namespace

PairForce contact_force(const ContactParams& p, const JkrPair& jkr, double alpha, const PairKinematics& k,
                        ContactState& s, double dt) {
  PairForce out;
  Vec3 d = k.xj - k.xi;
  double dist = norm(d);
  double delta = k.ri + k.rj - dist;
  s.delta = delta;
  if (!s.active) {
    if (delta < 0.0) return out;
    s = ContactState{};
    s.active = true;
    s.delta = delta;
  } else if (delta < -break_separation(p, jkr)) {
    s = ContactState{};
    s.delta = delta;
    return out;
  }
  const Vec3 n = d / dist;  // from i to j
  s.a = jkr.a_of_delta(delta, s.a);
  const double a = s.a;
  const double Fne = jkr.force_of_a(a);
  const double mstar = k.mi * k.mj / (k.mi + k.mj);
  const double eta_n = p.damping ? alpha * std::sqrt(mstar * jkr.stiffness(a)) : 0.0;

  // Lever arms to the contact plane (sum to dist).
  const double li = (dist * dist + k.ri * k.ri - k.rj * k.rj) / (2.0 * dist);
  const double lj = dist - li;
  const Vec3 vrel = k.vi - k.vj + cross(li * k.wi + lj * k.wj, n);
  const double ddelta_dt = dot(vrel, n);
  const Vec3 vs = vrel - ddelta_dt * n;

  const double Fn = Fne + eta_n * ddelta_dt;  // > 0 repulsive
  out.f_on_i = -Fn * n;

  Vec3 ft;
  if (p.tangential == TangentialModel::seed) {
    double vs_mag = norm(vs);
    if (vs_mag > 0.0) {
      double mag = std::min(p.friction * std::abs(Fn), eta_n * vs_mag);
      ft = (-mag / vs_mag) * vs;
    }
  } else {
    const double kt = 8.0 * p.gstar() * a;
    const double eta_t = eta_n;
    const double flim = p.friction * std::abs(Fne + 2.0 * jkr.Fc);
    rotate_into_plane(s.xi_t, n);
    s.xi_t += vs * dt;
    ft = -kt * s.xi_t - eta_t * vs;
    double fmag = norm(ft);
    if (fmag > flim) {
      ft *= flim / fmag;
      s.xi_t = -(ft + eta_t * vs) / kt;
    }
    const double limit_base = p.friction * std::abs(Fne + 2.0 * jkr.Fc);
    if (p.twisting) {
      const double kq = 0.5 * kt * a * a;
      const double eta_q = 0.5 * eta_t * a * a;
      const double wq = dot(k.wi - k.wj, n);
      s.xi_q += wq * dt;
      double mq = -kq * s.xi_q - eta_q * wq;
      const double mlim = 2.0 / 3.0 * a * limit_base;
      if (std::abs(mq) > mlim) {
        mq = std::copysign(mlim, mq);
        s.xi_q = -(mq + eta_q * wq) / kq;
      }
      out.t_on_i += mq * n;
      out.t_on_j -= mq * n;
    }
    if (p.rolling) {
      const double x = a / jkr.a0;
      const double kr = 4.0 * jkr.Fc * x * std::sqrt(x);
      rotate_into_plane(s.xi_r, n);
      s.xi_r += (jkr.R * dt) * cross(k.wi - k.wj, n);
      const double xi_crit = p.rolling_angle * jkr.R;
      double xr = norm(s.xi_r);
      if (xr > xi_crit) s.xi_r *= xi_crit / xr;
      Vec3 mr = -kr * cross(n, s.xi_r);
      out.t_on_i += mr;
      out.t_on_j -= mr;
    }
  }
  out.f_on_i += ft;
  out.t_on_i += li * cross(n, ft);
  out.t_on_j += lj * cross(n, ft);
  return out;
}

}  // namespace agglo::dem
