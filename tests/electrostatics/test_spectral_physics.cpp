// Spectral solver against docs/model.md §B.4: the reference table, the independent two-sphere reference,
// BSL App. C, the unequal-sphere value, uniform field, invariants (Newton 3, F = -dU/dx, net
// charge, zero torque).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <omp.h>

#include "agglo/core/error.hpp"
#include "agglo/electrostatics/solver.hpp"
#include "es_test_helpers.hpp"
#include "two_sphere_reference.hpp"

using namespace agglo;
using namespace agglo::es;
using namespace agglo::es::testing;

namespace {

std::unique_ptr<Solver> spectral(double target = 1e-4, int max_degree = 0, double tol = 1e-6) {
  SolverOptions o;
  o.solver = "spectral";
  o.target_accuracy = target;
  o.max_degree = max_degree;
  o.tolerance = tol;
  return make_solver(o);
}

double reference_table_force(double kappa, double h, double c1, double c2, int N) {
  testref::TwoSphereInput in;
  in.a1 = in.a2 = kR;
  in.t = (2 + h) * kR;
  in.k1 = in.k2 = kappa;
  in.q1 = c1 * kQ0;
  in.q2 = c2 * kQ0;
  in.N = N;
  return testref::solve_two_spheres(in).fz2 / (kQ0 * kQ0 / (4 * pi * eps0 * kR * kR));
}

}  // namespace

TEST(TwoSphereReference, ReproducesTable) {
  // The independent reference must itself reproduce docs/model.md §B.4 to the printed digits.
  for (const auto& e : model_b4_table()) {
    int N = e.h >= 1 ? 40 : (e.h >= 0.1 ? 80 : 160);
    double f = reference_table_force(e.kappa, e.h, e.c1, e.c2, N);
    EXPECT_NEAR(f, e.value, table_rounding(e.value) + 1e-7 * std::abs(e.value))
        << "kappa " << e.kappa << " h " << e.h << " (" << e.c1 << "," << e.c2 << ")";
  }
}

TEST(SpectralTable, GapsAtLeastPointOneWithinOneInAMillion) {
  auto s = spectral(1e-6);
  for (const auto& e : model_b4_table()) {
    if (e.h < 0.1) continue;
    Solution sol;
    double f = table_force(*s, e.kappa, e.h, e.c1, e.c2, &sol);
    double ref = reference_table_force(e.kappa, e.h, e.c1, e.c2, e.h >= 1 ? 40 : 80);
    EXPECT_NEAR(f, ref, 1e-6 * std::abs(ref))
        << "kappa " << e.kappa << " h " << e.h << " (" << e.c1 << "," << e.c2 << ") L " << sol.stats.degree;
    EXPECT_NEAR(f, e.value, 1e-6 * std::abs(e.value) + table_rounding(e.value));
  }
}

TEST(SpectralTable, GapPointZeroOneWithinOneInTenThousandAtDefaults) {
  auto s = spectral();  // default target accuracy 1e-4
  for (const auto& e : model_b4_table()) {
    if (e.h >= 0.1) continue;
    Solution sol;
    double f = table_force(*s, e.kappa, e.h, e.c1, e.c2, &sol);
    EXPECT_NEAR(f, e.value, 1e-4 * std::abs(e.value))
        << "kappa " << e.kappa << " (" << e.c1 << "," << e.c2 << ") L " << sol.stats.degree;
    expect_newton_third_law(sol, 1e-8);
  }
}

TEST(SpectralPhysics, UnequalSpheres) {
  // a2 = 0.5 a1, kappa 10, charges (1,1), gap 0.05 a1: -0.0458886 (like charges attract).
  auto s = spectral(1e-6);
  Problem p = two_spheres(kR, 0.5 * kR, 0.05 * kR, 10, 10, kQ0, kQ0);
  Solution sol = s->solve(p);
  double f = sol.force[1].z / (kQ0 * kQ0 / (4 * pi * eps0 * kR * kR));
  EXPECT_NEAR(f, -0.0458886, 1e-6 * 0.0458886 + table_rounding(0.0458886));
  expect_newton_third_law(sol, 1e-6);
}

TEST(SpectralPhysics, PointChargeNearNeutralSphere) {
  // BSL App. C: q at surface distance d = 0.1 r0 from a neutral sphere with kappa 10:
  // U = -0.124066681 q^2 / (eps0 r0). The point charge is a tiny sphere (radius 1e-4 r0) with
  // kappa = kappa0 = 1: it is not polarisable and its exterior field is exactly that of q at its
  // centre; its self energy q^2/(8 pi eps0 r_tiny) is subtracted.
  const double r0 = kR, d = 0.1 * r0, rt = 1e-4 * r0, q = kQ0;
  Problem p;
  p.spheres.push_back({Vec3{0, 0, 0}, r0, 0.0, 10.0});
  p.spheres.push_back({Vec3{0, 0, r0 + d}, rt, q, 1.0});
  SolverOptions o;
  o.target_accuracy = 1e-8;
  o.max_degree_limit = 160;
  auto s = make_solver(o);
  Solution sol = s->solve(p);
  double U = sol.energy - q * q / (8 * pi * eps0 * rt);
  double expect = -0.124066681 * q * q / (eps0 * r0);
  EXPECT_NEAR(U, expect, 1e-7 * std::abs(expect)) << "L " << sol.stats.degree;
  // the series of BSL App. C (test-side) gives the same number
  EXPECT_NEAR(testref::point_charge_sphere_energy(q, d, r0, 10.0), expect, 1e-8 * std::abs(expect));
  expect_newton_third_law(sol, 1e-8);
}

TEST(SpectralPhysics, UniformFieldDipoleAndInducedCharge) {
  for (double kappa : {2.5, 15.0}) {
    auto s = spectral();
    expect_uniform_field_sphere(*s, kappa, 0.0, Vec3{1e5, -2e5, 5e4}, 1e-12, 1e-12);
    auto s2 = spectral();
    expect_uniform_field_sphere(*s2, kappa, 3 * kQ0, Vec3{0, 0, 3e5}, 1e-12, 1e-12);
  }
}

TEST(SpectralPhysics, NetChargeIsFreeChargeOverKappa0) {
  auto s = spectral(1e-6);
  expect_net_charges_far_field(*s, 10, 2.5, 1.0, 1e-7);
  expect_net_charges_far_field(*s, 10, 2.5, 2.0, 1e-7);
}

TEST(SpectralPhysics, ForceIsMinusEnergyGradient) {
  // Fixed L so that U(x) is one smooth function; random 3-sphere configuration, moderate gaps.
  // (No applied field: U = 1/2 \int phi sigma_f is the potential of the forces only without one.)
  auto s = spectral(1e-4, 30, 1e-13);
  Problem p;
  p.spheres.push_back({Vec3{0, 0, 0}, kR, 2 * kQ0, 5.0});
  p.spheres.push_back({Vec3{2.3 * kR, 0.4 * kR, 0.2 * kR}, 0.8 * kR, -kQ0, 15.0});
  p.spheres.push_back({Vec3{0.5 * kR, 2.4 * kR, -0.6 * kR}, 1.2 * kR, 0.5 * kQ0, 2.5});
  double fscale = kQ0 * kQ0 / (4 * pi * eps0 * kR * kR);
  for (int body = 0; body < 3; ++body)
    for (int axis = 0; axis < 3; ++axis) {
      auto [F, G] = force_and_energy_gradient(*s, p, body, axis, 1e-4 * kR);
      EXPECT_NEAR(F, G, 1e-6 * fscale) << "body " << body << " axis " << axis;
    }
}

TEST(SpectralPhysics, TorqueVanishesOnIsotropicSpheres) {
  // A uniformly charged isolated sphere feels no torque; neither does any isotropic dielectric
  // sphere in the fields of others (its energy is invariant under its own rotation).
  auto s = spectral(1e-6);
  Problem p1;
  p1.spheres.push_back({Vec3{1e-6, 0, 0}, kR, 5 * kQ0, 7.0});
  Solution a = s->solve(p1);
  EXPECT_EQ(norm(a.torque[0]), 0.0);
  EXPECT_EQ(norm(a.force[0]), 0.0);
  Problem p = two_spheres(kR, 0.7 * kR, 0.2 * kR, 10, 3, kQ0, -2 * kQ0);
  p.spheres[1].center.x += 0.5 * kR;
  p.external_field = Vec3{3e4, 1e4, 0};
  Solution b = s->solve(p);
  double fscale = norm(b.force[0]) * kR;
  for (const auto& t : b.torque) EXPECT_LE(norm(t), 1e-6 * fscale) << t.x << " " << t.y << " " << t.z;
}

TEST(SpectralPhysics, AgreesWithIndependentReferenceOnRandomPairs) {
  std::mt19937 g(2024);
  std::uniform_real_distribution<double> U(0, 1);
  auto s = spectral(1e-6);
  for (int c = 0; c < 8; ++c) {
    testref::TwoSphereInput in;
    in.a1 = kR * (0.5 + U(g));
    in.a2 = kR * (0.5 + U(g));
    double gap = kR * std::pow(10.0, -1.5 + 1.5 * U(g));  // 0.03 .. 1 R
    in.t = in.a1 + in.a2 + gap;
    in.k1 = 1 + 14 * U(g);
    in.k2 = 1 + 14 * U(g);
    in.k0 = (c % 3 == 0) ? 2.0 : 1.0;
    in.q1 = kQ0 * (2 * U(g) - 1);
    in.q2 = kQ0 * (2 * U(g) - 1);
    in.N = 150;
    auto ref = testref::solve_two_spheres(in);
    // same pair, rotated off the z axis
    Vec3 e{0.3, -0.5, 0.81};
    e = e / norm(e);
    Problem p;
    p.medium_permittivity = in.k0;
    p.spheres.push_back({Vec3{1e-6, 2e-6, 0}, in.a1, in.q1, in.k1});
    p.spheres.push_back({Vec3{1e-6, 2e-6, 0} + e * in.t, in.a2, in.q2, in.k2});
    Solution sol = s->solve(p);
    double f2 = dot(sol.force[1], e);
    double fscale = std::max({std::abs(ref.fz2), std::abs(in.q1 * in.q2) / (4 * pi * eps0 * in.t * in.t),
                              in.q1 * in.q1 / (4 * pi * eps0 * in.t * in.t) * 1e-3});
    EXPECT_NEAR(f2, ref.fz2, 1e-6 * fscale) << "case " << c << " L " << sol.stats.degree;
    EXPECT_NEAR(sol.energy, ref.energy, 1e-8 * std::abs(ref.energy)) << "case " << c;
    EXPECT_NEAR(norm(sol.force[1] - e * f2), 0.0, 1e-9 * fscale);
    EXPECT_NEAR(ref.fz1, -ref.fz2, 1e-8 * fscale);
  }
}

// The pair products of a solve run in parallel (blocks of pairs, added in pair order): forces, torques,
// energy and iteration count must not depend on the thread count. 16 charged, polarisable spheres of
// radii 0.95-1.05 r on a 2x2x4 lattice of 2.105 r (gaps down to 0.005 r) in a field, at accuracy 1e-7
// (degree 39), so that a block has the work to run in parallel: checked through the solver's count of
// such blocks, or the comparison could pass vacuously.
TEST(SpectralPhysics, SolutionDoesNotDependOnTheThreadCount) {
  Problem p;
  int n = 0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int c = 0; c < 4; ++c, ++n)
        p.spheres.push_back({Vec3(a, b, c) * (2.105 * kR), kR * (0.95 + 0.05 * (n % 3)),
                             (n % 2 ? 1.0 : -0.7) * kQ0, 10.0 + n % 5});
  p.external_field = Vec3{2e4, -1e4, 3e4};
  const int saved = omp_get_max_threads();
  auto run = [&](int threads) {
    omp_set_num_threads(threads);
    return spectral(1e-7)->solve(p);
  };
  const Solution one = run(1);
  EXPECT_GE(one.stats.degree, 10);
  for (int threads : {2, 3}) {
    const Solution s = run(threads);
    EXPECT_GT(s.stats.extra.at("parallel_pair_blocks").get<long>(), 0) << "no block to run in parallel";
    EXPECT_EQ(s.energy, one.energy) << threads << " threads";
    EXPECT_EQ(s.stats.iterations, one.stats.iterations) << threads << " threads";
    for (std::size_t i = 0; i < p.spheres.size(); ++i) {
      EXPECT_TRUE(s.force[i].x == one.force[i].x && s.force[i].y == one.force[i].y && s.force[i].z == one.force[i].z) << "sphere " << i << ", " << threads << " threads";
      EXPECT_TRUE(s.torque[i].x == one.torque[i].x && s.torque[i].y == one.torque[i].y && s.torque[i].z == one.torque[i].z) << "sphere " << i << ", " << threads << " threads";
    }
  }
  omp_set_num_threads(saved);
}

TEST(SpectralErrors, OverlapAndBadInputThrow) {
  auto s = spectral();
  Problem p = two_spheres(kR, kR, -0.01 * kR, 2, 2, kQ0, kQ0);
  EXPECT_THROW(s->solve(p), NumericalError);
  Problem q = two_spheres(kR, kR, 0.1 * kR, 0.0, 2, kQ0, kQ0);
  EXPECT_THROW(s->solve(q), NumericalError);
  Problem r = two_spheres(kR, 0.0, 0.1 * kR, 2, 2, kQ0, kQ0);
  EXPECT_THROW(s->solve(r), NumericalError);
}

TEST(SpectralErrors, GmresNotConvergingThrows) {
  SolverOptions o;
  o.max_iterations = 2;
  o.tolerance = 1e-12;
  auto s = make_solver(o);
  Problem p = two_spheres(kR, kR, 0.01 * kR, 15, 15, kQ0, -kQ0);
  EXPECT_THROW(s->solve(p), NumericalError);
}
