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

// Inline: the contact law calls them for every contact and step.
inline double JkrPair::a_of_delta(double delta, double a_guess) const {
  const double d = delta / (kJkrCbrt6 * deltaC);  // target of f(s) = 2 s^4 - 4/3 s
  if (d <= -kJkrSMin) return kJkrSMin * kJkrSMin * a0;  // at/below the break point: the turning point
  // f is convex and increasing for s >= s_min. From a warm start near the root Newton converges in a
  // few steps from either side (from the left it lands right of the root, then decreases
  // monotonically). Without a usable guess (or close to the turning point, where f' -> 0) start from
  // an upper bound of the root.
  double s;
  if (a_guess > 0.0 && a_guess > 1.2 * kJkrSMin * kJkrSMin * a0) {
    s = std::sqrt(a_guess / a0);
  } else {
    s = std::max(1.0, std::sqrt(std::sqrt(std::max(d, 0.0) / 2.0 + 1.0)) + 0.5);
  }
  // Quadratic convergence; near the turning point (d -> -s_min) it degrades to linear, hence the cap.
  for (int it = 0; it < 100; ++it) {
    double s3 = s * s * s;
    double f = 2.0 * s3 * s - 4.0 / 3.0 * s - d;
    double fp = 8.0 * s3 - 4.0 / 3.0;
    double s_new = std::max(s - f / fp, kJkrSMin);
    double change = std::abs(s_new - s);
    s = s_new;
    if (change <= 4e-16 * s) break;
  }
  return s * s * a0;
}

inline double JkrPair::force_of_a(double a) const {
  double x = a / a0;
  return 4.0 * Fc * (x * x * x - x * std::sqrt(x));
}

// Overlap at which the pair force is the pull-off minimum -F_C: delta = -0.48075 delta_C.
inline constexpr double kDeltaAtMinForce = -0.480750157;  // (2^(-2/3)) mapped through delta(a)

}  // namespace agglo::dem
