#pragma once
// Solver-generic checks of docs/model.md §B.4, shared by the spectral/coulomb tests and (later) the BEM
// tests: every helper takes an es::Solver& and returns numbers or runs gtest expectations with
// caller-given tolerances.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "agglo/core/constants.hpp"
#include "agglo/electrostatics/solver.hpp"

namespace agglo::es::testing {

using constants::eps0;
using constants::pi;

// docs/model.md §B.4 table: equal spheres of radius R, both kappa_p, charges c1 Q0 and c2 Q0, gap h.
// value = force on sphere 2 along the line of centres / F0, F0 = Q0^2 / (4 pi eps0 R^2).
struct TableEntry {
  double kappa, h, c1, c2, value;
};

inline std::vector<TableEntry> model_b4_table() {
  const double cs[4][2] = {{1, 1}, {1, -1}, {1, 10}, {1, 0}};
  const double kh[6][2] = {{2.5, 1}, {2.5, 0.1}, {2.5, 0.01}, {10, 1}, {10, 0.1}, {10, 0.01}};
  const double v[6][4] = {{0.104797, -0.118240, 0.775739, -0.00336085},
                          {0.187550, -0.297855, -0.358169, -0.0275762},
                          {0.199164, -0.353847, -1.14068, -0.0386707},
                          {0.0980225, -0.128205, 0.369038, -0.00754552},
                          {0.158630, -0.494063, -5.20623, -0.0838583},
                          {0.166242, -0.913658, -13.4727, -0.186854}};
  std::vector<TableEntry> t;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 4; ++c) t.push_back({kh[r][0], kh[r][1], cs[c][0], cs[c][1], v[r][c]});
  return t;
}

// Half a unit of the last printed (6th significant) digit of a table value.
inline double table_rounding(double v) {
  return 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(v))) - 5);
}

inline constexpr double kR = 10e-6;     // radius used for the dimensionless cases [m]
inline constexpr double kQ0 = 1e-14;    // charge unit [C]

// Sphere 1 at the origin, sphere 2 at +z, surface gap h (in units of R).
inline Problem two_spheres(double R1, double R2, double gap, double k1, double k2, double q1, double q2,
                           double k0 = 1.0) {
  Problem p;
  p.medium_permittivity = k0;
  p.spheres.push_back({Vec3{0, 0, 0}, R1, q1, k1});
  p.spheres.push_back({Vec3{0, 0, R1 + R2 + gap}, R2, q2, k2});
  return p;
}

// Force on sphere 2 along +z divided by F0 (the table's quantity).
inline double table_force(Solver& s, double kappa, double h, double c1, double c2, Solution* out = nullptr) {
  Problem p = two_spheres(kR, kR, h * kR, kappa, kappa, c1 * kQ0, c2 * kQ0);
  Solution sol = s.solve(p);
  if (out) *out = sol;
  const double F0 = kQ0 * kQ0 / (4 * pi * eps0 * kR * kR);
  return sol.force[1].z / F0;
}

// |F_1 + F_2| <= rel * max |F_i| for a two-body solution (and all-body sum in general).
inline void expect_newton_third_law(const Solution& s, double rel) {
  Vec3 sum;
  double fmax = 0;
  for (const auto& f : s.force) {
    sum += f;
    fmax = std::max(fmax, norm(f));
  }
  EXPECT_LE(norm(sum), rel * fmax) << "net force " << sum.x << " " << sum.y << " " << sum.z;
}

// Central finite difference of the energy for body `body` along `axis` with step `step` [m];
// returns {F_axis, -dU/dx}.
inline std::pair<double, double> force_and_energy_gradient(Solver& s, const Problem& p, int body, int axis,
                                                           double step) {
  Solution s0 = s.solve(p);
  Problem pp = p, pm = p;
  pp.spheres[body].center[axis] += step;
  pm.spheres[body].center[axis] -= step;
  double Up = s.solve(pp).energy, Um = s.solve(pm).energy;
  return {s0.force[body][axis], -(Up - Um) / (2 * step)};
}

// Single sphere (radius R, kappa, charge q) in a uniform field E0 in vacuum: force q E0, torque 0,
// sigma_b = 3 eps0 (kappa-1)/(kappa+2) E0.n at every surface sample (+ sigma_f (1/kappa0 - 1) = 0).
inline void expect_uniform_field_sphere(Solver& s, double kappa, double q, const Vec3& E0, double tol_force,
                                        double tol_sigma) {
  Problem p;
  p.spheres.push_back({Vec3{1e-6, -2e-6, 3e-6}, kR, q, kappa});
  p.external_field = E0;
  Solution sol = s.solve(p);
  Vec3 fe = E0 * q;
  EXPECT_LE(norm(sol.force[0] - fe), tol_force * norm(fe) + 1e-30);
  EXPECT_LE(norm(sol.torque[0]), tol_force * (norm(fe) + norm(E0) * kQ0) * kR);
  const double c = 3 * eps0 * (kappa - 1) / (kappa + 2);
  double smax = c * norm(E0);
  double worst = 0;
  auto samples = s.surface();
  ASSERT_FALSE(samples.empty());
  for (const auto& ss : samples) {
    double expect = c * dot(E0, ss.normal);
    worst = std::max(worst, std::abs(ss.sigma_bound - expect));
    EXPECT_NEAR(ss.sigma_free, q / (4 * pi * kR * kR), 1e-12 * std::abs(q) / (kR * kR) + 1e-300);
  }
  EXPECT_LE(worst, tol_sigma * smax);
}

// Net charge of each body = q / kappa0 seen from afar: two spheres 1000 radii apart in a medium
// kappa0 attract/repel with q1 q2 / (4 pi eps0 kappa0 t^2) up to polarisation terms O((R/t)^3).
inline void expect_net_charges_far_field(Solver& s, double k1, double k2, double k0, double rel) {
  const double t = 1000 * kR;
  Problem p = two_spheres(kR, 0.5 * kR, t - 1.5 * kR, k1, k2, 3 * kQ0, -2 * kQ0, k0);
  Solution sol = s.solve(p);
  double expect = p.spheres[0].charge * p.spheres[1].charge / (4 * pi * eps0 * k0 * t * t);
  EXPECT_NEAR(sol.force[1].z, expect, rel * std::abs(expect));  // positive = repulsion
  EXPECT_NEAR(sol.force[0].z, -expect, rel * std::abs(expect));
}

}  // namespace agglo::es::testing
