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
  double t_per_delta = 0.0;  // 1 / (6^(1/3) delta_C) [1/m] (derived: set by make() and derive())

  static JkrPair make(double R, double Estar, double gamma);
  // The derived constant t_per_delta from deltaC (make() calls it; so must code that sets deltaC by hand).
  void derive() { t_per_delta = 1.0 / (kJkrCbrt6 * deltaC); }

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

inline double JkrPair::force_of_a(double a) const {
  double x = a / a0;
  return 4.0 * Fc * (x * x * x - x * std::sqrt(x));
}

// The fast path's contact radius (docs/benchmarks_dem.md §8; issue 27): the root s = (a/a0)^(1/2) of
//   f(s) = 2 s^4 - 4/3 s = t,   t = delta / (6^(1/3) delta_C) >= -s_min,   s_min = 6^(-1/3),
// without a warm start and without a convergence test. With w = (t + s_min)^(1/2) the equation reads
// (s - s_min) q(s)^(1/2) = w, q(s) = 2 s^2 + 4 s_min s + 6 s_min^2, so s(w) is smooth down to the turning
// point w = 0 (where s(t) has a square-root singularity). s(w) is tabulated as one cubic per interval of
// w in [0, kJkrTableW) (kJkrTableCells intervals; the cubics interpolate the root at the four Chebyshev
// points of each interval, computed once at start-up in long double), then polished by one Halley step
//   s <- s - 2 f' (f - t) / (2 f'^2 - (f - t) f'').
// Table error <= 1.2e-8 relative; after the Halley step the root is within a few ulp of the exact root of
// t for t + s_min >= 1e-2, within 1e-13 for 1e-6 <= t + s_min < 1e-2 and within 1e-8 below, the same
// order as a_of_delta's own (the root is ill-conditioned there: ds/dt = 1/f'(s) -> infinity); tested in
// tests/dem/test_jkr.cpp (Jkr.FastRootAgainstExactRoot). Beyond the table (t >= kJkrTableW^2 - s_min,
// about 63 delta_C 6^(1/3)) the Newton iteration of a_of_delta from its cold start.
inline constexpr int kJkrTableCells = 128;
inline constexpr double kJkrTableW = 8.0;
struct JkrRootTable {
  double c[kJkrTableCells][4];  // s = c0 + c1 x + c2 x^2 + c3 x^3, x = w kJkrTableCells / kJkrTableW - cell
};
extern const JkrRootTable kJkrRootTable;

// s = (a/a0)^(1/2) for t = delta t_per_delta >= -s_min (an engaged contact; t below -s_min gives s_min).
[[gnu::always_inline]] inline double jkr_root_fast(double t) {
  const double x = std::sqrt(std::max(t + kJkrSMin, 0.0)) * (kJkrTableCells / kJkrTableW);
  if (!(x < kJkrTableCells)) [[unlikely]] {  // beyond the table: the iteration of a_of_delta, cold start
    JkrNewton n;
    n.t = t;
    n.s = std::max(1.0, std::sqrt(std::sqrt(t / 2.0 + 1.0)) + 0.5);
    for (int it = 0; it < kJkrNewtonCap && n.step(); ++it) {
    }
    return n.s;
  }
  const int cell = static_cast<int>(x);
  const double u = x - cell;
  const double* c = kJkrRootTable.c[cell];
  const double s = c[0] + u * (c[1] + u * (c[2] + u * c[3]));
  const double s3 = s * s * s;
  const double g = 2.0 * s3 * s - 4.0 / 3.0 * s - t;
  const double gp = 8.0 * s3 - 4.0 / 3.0;
  const double den = 2.0 * gp * gp - g * (24.0 * s * s);
  const double step = den != 0.0 ? 2.0 * g * gp / den : 0.0;  // (0 / 0 only exactly at the turning point)
  return std::max(s - step, kJkrSMin);
}

// The fast path's radius and elastic force from the root s (same formulas as a = s^2 a0 and force_of_a):
//   a = s^2 a0,  F_ne = 4 F_C s^3 (s^3 - 1)
[[gnu::always_inline]] inline double jkr_force_of_root(const JkrPair& p, double s) {
  const double s3 = s * s * s;
  return 4.0 * p.Fc * s3 * (s3 - 1.0);
}

// Overlap at which the pair force is the pull-off minimum -F_C: delta = -0.48075 delta_C.
inline constexpr double kDeltaAtMinForce = -0.480750157;  // (2^(-2/3)) mapped through delta(a)

}  // namespace agglo::dem
