#pragma once
// Energy of one JKR contact under a constant load, and the barrier it must climb to break
// (Johnson-Kendall-Roberts with Marshall's hysteresis, dem/contact/jkr_normal.hpp; used by intact.hpp).
// In the variable x = a/a0 of dem/jkr.hpp, c = 6^(1/3):
//   delta(x) = c delta_C (2 x^2 - 4/3 x^(1/2)),  F(x) = 4 F_C (x^3 - x^(3/2))   (F > 0 repulsive)
// The elastic-adhesive potential phi with F = d phi / d delta (overlap up, distance down) is, integrated
// in closed form along the stable branch x >= x_b = 6^(-2/3) (delta(x_b) = -delta_C):
//   phi(x) = 4 c F_C delta_C (4/5 x^5 - 4/3 x^(7/2) + 1/3 x^2)          [J], up to a constant
// (minimum at x = 1, F = 0; phi(x_b) - phi(1) = 1.5426 F_C delta_C, the work to pull an unloaded contact
// from equilibrium to Marshall's break point). A constant load L [N] that pulls the two spheres together
// (L > 0: attraction, L < 0: the pair is pushed apart) adds -L delta:
//   psi(x) = phi(x) - L delta(x),   d psi/dx = c delta_C (4x - 2/3 x^(-1/2)) (F(x) - L)
// so psi is smallest where F = L on the rising branch x >= 2^(-2/3), and the contact breaks once delta
// falls below -s delta_C (s = 1: "marshall", s = 0.48075: "lammps", at the force minimum -F_C). Between
// the break point x_s and the minimum, psi has its largest value either at x_s or, when -F_C < L < F(x_s),
// where F = L on the falling branch (past it the pair separates by itself). The barrier is
//   B(L) = max_{x_s <= x <= x_min} psi(x) - psi(x_min)   [J]   (0 when L <= -F_C: no stable contact).
#include "agglo/dem/jkr.hpp"

namespace agglo::impact {

// The state of a loaded contact relative to its barrier (energies in F_C delta_C).
struct LoadedContact {
  double x_min = 0.0;    // a/a0 at the minimum of psi (F = L); 0 without a stable minimum
  double x_peak = 0.0;   // a/a0 where psi is largest between the break point and x_min
  double barrier = 0.0;  // psi(x_peak) - psi(x_min) [F_C delta_C]
};

// phi(x) / (F_C delta_C) with the constant chosen as above.
double jkr_potential(double x);
// psi(x) / (F_C delta_C) for the load l = L / F_C.
double loaded_potential(double x, double l);
// Minimum, peak and barrier for the load l = L / F_C and the break point delta = -s delta_C (0 < s <= 1).
LoadedContact loaded_contact(double l, double s);
// a/a0 at the break point delta = -s delta_C on the stable branch, and at the formation point delta = 0.
double break_x(double s);
double formation_x();

}  // namespace agglo::impact
