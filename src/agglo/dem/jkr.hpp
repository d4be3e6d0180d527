#pragma once
// JKR adhesive normal contact (Johnson-Kendall-Roberts; Marshall 2009 J. Comput. Phys. 228, 1541;
// docs/model.md §A.2). Units: SI. F > 0 is repulsive.
//   F_C  = 3 pi gamma R                       pull-off force [N]
//   a0   = (9 pi gamma R^2 / E*)^(1/3)        equilibrium contact radius [m]
//   delta_C = a0^2 / (2 6^(1/3) R)            critical overlap [m]
//   delta/delta_C = 6^(1/3) [2 (a/a0)^2 - 4/3 (a/a0)^(1/2)]
//   F_ne = 4 F_C [(a/a0)^3 - (a/a0)^(3/2)]
// gamma is the surface energy per surface (work of adhesion 2 gamma).
#include <algorithm>
#include <cmath>

namespace agglo::dem {

extern const double kJkrCbrt6;  // 6^(1/3)
extern const double kJkrSMin;   // 6^(-1/3): s = (a/a0)^(1/2) at delta = -delta_C (d delta/ds = 0)

struct JkrPair {
  double R = 0.0;       // effective radius r_i r_j/(r_i + r_j) [m]
  double Estar = 0.0;   // effective modulus, 1/E* = (1-nu_i^2)/E_i + (1-nu_j^2)/E_j [Pa]
  double gamma = 0.0;   // surface energy [J/m^2]
  double Fc = 0.0;      // pull-off force [N]
  double a0 = 0.0;      // equilibrium contact radius [m]
  double deltaC = 0.0;  // critical overlap [m]

  static JkrPair make(double R, double Estar, double gamma);

  // Overlap for contact radius a (the JKR relation; valid on the stable branch a >= 6^(-2/3) a0).
  double delta_of_a(double a) const;
  // Contact radius for overlap delta >= -delta_C, Newton on 2 s^4 - 4/3 s - delta/(6^(1/3) delta_C) = 0,
  // s = (a/a0)^(1/2) >= 6^(-1/3); `a_guess` (<= 0: none) warm-starts the iteration.
  [[gnu::always_inline]] double a_of_delta(double delta, double a_guess = 0.0) const;
  // Elastic normal force for contact radius a.
  double force_of_a(double a) const;
  // Normal stiffness k_N = (4/3) E* a [N/m].
  double stiffness(double a) const { return 4.0 / 3.0 * Estar * a; }
  // Equilibrium overlap delta0 = a0^2 / (3 R).
  double delta_equilibrium() const { return a0 * a0 / (3.0 * R); }
};

// The Newton iteration of a_of_delta in parts, so that a_of_delta and a_of_delta_pair run the same
// operations: t = delta/(6^(1/3) delta_C), the start s, and one step.
struct JkrNewton {
  double t = 0.0;  // target of f(s) = 2 s^4 - 4/3 s
  double s = 0.0;  // iterate s = (a/a0)^(1/2)
  // One Newton step; false once the change is within 4e-16 s (converged).
  [[gnu::always_inline]] bool step() {
    double s3 = s * s * s;
    double f = 2.0 * s3 * s - 4.0 / 3.0 * s - t;
    double fp = 8.0 * s3 - 4.0 / 3.0;
    double s_new = std::max(s - f / fp, kJkrSMin);
    double change = std::abs(s_new - s);
    s = s_new;
    return !(change <= 4e-16 * s);
  }
};

// Inline: the contact law calls them for every contact and step.
// The start of a_of_delta: false when delta is at/below the break point (a is the turning point's radius).
[[gnu::always_inline]] inline bool jkr_newton_start(const JkrPair& p, double delta, double a_guess, JkrNewton& n) {
  n.t = delta / (kJkrCbrt6 * p.deltaC);
  if (n.t <= -kJkrSMin) return false;
  // f is convex and increasing for s >= s_min. From a warm start near the root Newton converges in a
  // few steps from either side (from the left it lands right of the root, then decreases
  // monotonically). Without a usable guess (or close to the turning point, where f' -> 0) start from
  // an upper bound of the root.
  if (a_guess > 0.0 && a_guess > 1.2 * kJkrSMin * kJkrSMin * p.a0) {
    n.s = std::sqrt(a_guess / p.a0);
  } else {
    n.s = std::max(1.0, std::sqrt(std::sqrt(std::max(n.t, 0.0) / 2.0 + 1.0)) + 0.5);
  }
  return true;
}

// Quadratic convergence; near the turning point (t -> -s_min) it degrades to linear, hence the cap of
// kJkrNewtonCap steps.
inline constexpr int kJkrNewtonCap = 100;

inline double JkrPair::a_of_delta(double delta, double a_guess) const {
  JkrNewton n;
  if (!jkr_newton_start(*this, delta, a_guess, n)) return kJkrSMin * kJkrSMin * a0;
  for (int it = 0; it < kJkrNewtonCap && n.step(); ++it) {
  }
  return n.s * n.s * a0;
}

// a[l] = p[l]->a_of_delta(delta[l], a[l]) for the lanes l < L (L even), bit for bit, with the L Newton
// iterations interleaved in two-double vectors (GCC vector extensions; IEEE operations lane by lane, the same
// as JkrNewton::step's): L independent chains of divisions, no branch per lane. A converged lane keeps its
// s (selected by mask), as a_of_delta stops; the loop ends when every lane has converged.
template <int L>
[[gnu::always_inline]] inline void a_of_delta_lanes(const JkrPair* const (&p)[L], const double (&delta)[L],
                                                    double* const (&a)[L]) {
  static_assert(L % 2 == 0);
  typedef double v2d __attribute__((vector_size(16)));
  typedef long long v2l __attribute__((vector_size(16)));
  constexpr int V = L / 2;
  v2d t[V], s[V];
  v2l run[V];
  bool solve[L];
  for (int l = 0; l < L; ++l) {
    JkrNewton n;
    solve[l] = jkr_newton_start(*p[l], delta[l], *a[l], n);
    t[l / 2][l % 2] = n.t;
    s[l / 2][l % 2] = solve[l] ? n.s : 1.0;
    run[l / 2][l % 2] = solve[l] ? -1 : 0;
  }
  const v2d smin = {kJkrSMin, kJkrSMin};
  const v2l sign = {static_cast<long long>(1ULL << 63), static_cast<long long>(1ULL << 63)};
  for (int it = 0; it < kJkrNewtonCap; ++it) {
    v2l any = {0, 0};
    for (int v = 0; v < V; ++v) {
      const v2d sv = s[v];
      const v2d s3 = sv * sv * sv;
      const v2d f = 2.0 * s3 * sv - 4.0 / 3.0 * sv - t[v];
      const v2d fp = 8.0 * s3 - 4.0 / 3.0;
      const v2d x = sv - f / fp;
      const v2l below = x < smin;  // std::max(x, s_min)
      const v2d s_new = (v2d)(((v2l)smin & below) | ((v2l)x & ~below));
      const v2d change = (v2d)((v2l)(s_new - sv) & ~sign);
      const v2l converged = change <= 4e-16 * s_new;
      s[v] = (v2d)(((v2l)s_new & run[v]) | ((v2l)sv & ~run[v]));
      run[v] &= ~converged;
      any |= run[v];
    }
    if ((any[0] | any[1]) == 0) break;
  }
  for (int l = 0; l < L; ++l) {
    const double sl = s[l / 2][l % 2];
    *a[l] = solve[l] ? sl * sl * p[l]->a0 : kJkrSMin * kJkrSMin * p[l]->a0;
  }
}

inline double JkrPair::force_of_a(double a) const {
  double x = a / a0;
  return 4.0 * Fc * (x * x * x - x * std::sqrt(x));
}

// Overlap at which the pair force is the pull-off minimum -F_C: delta = -0.48075 delta_C.
inline constexpr double kDeltaAtMinForce = -0.480750157;  // (2^(-2/3)) mapped through delta(a)

}  // namespace agglo::dem
