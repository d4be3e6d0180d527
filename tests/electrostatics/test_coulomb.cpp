// Coulomb solver: exact for kappa_p = kappa_0 (docs/model.md §B.2 item 1), and equal to the spectral
// solver (which is exact there too) for random configurations.
#include <gtest/gtest.h>

#include <random>

#include "es_test_helpers.hpp"
#include "two_sphere_reference.hpp"

using namespace agglo;
using namespace agglo::es;
using namespace agglo::es::testing;

TEST(Coulomb, ExactForKappaOneAgainstReference) {
  SolverOptions o;
  o.solver = "coulomb";
  auto s = make_solver(o);
  for (double h : {1.0, 0.1, 0.01}) {
    for (double k0 : {1.0, 3.0}) {
      testref::TwoSphereInput in;
      in.a1 = kR;
      in.a2 = 0.6 * kR;
      in.t = in.a1 + in.a2 + h * kR;
      in.k1 = in.k2 = in.k0 = k0;
      in.q1 = 2 * kQ0;
      in.q2 = -0.7 * kQ0;
      in.N = 20;
      auto ref = testref::solve_two_spheres(in);
      Problem p = two_spheres(in.a1, in.a2, h * kR, k0, k0, in.q1, in.q2, k0);
      Solution sol = s->solve(p);
      double exact = in.q1 * in.q2 / (4 * pi * eps0 * k0 * in.t * in.t);
      EXPECT_NEAR(sol.force[1].z, exact, 1e-14 * std::abs(exact));
      EXPECT_NEAR(ref.fz2, exact, 1e-10 * std::abs(exact));  // the reference agrees: no induced charge
      EXPECT_NEAR(sol.energy, ref.energy, 1e-12 * std::abs(ref.energy));
      expect_newton_third_law(sol, 1e-14);
    }
  }
}

TEST(Coulomb, MatchesSpectralForUnitPermittivity) {
  std::mt19937 g(7);
  std::uniform_real_distribution<double> U(-1, 1);
  SolverOptions oc, os;
  oc.solver = "coulomb";
  auto c = make_solver(oc), s = make_solver(os);
  Problem p;
  for (int i = 0; i < 6; ++i) p.spheres.push_back({Vec3{3 * kR * i, 2 * kR * U(g), kR * U(g)}, kR, kQ0 * U(g), 1.0});
  p.external_field = Vec3{1e4, -3e4, 2e4};
  Solution a = c->solve(p), b = s->solve(p);
  for (int i = 0; i < 6; ++i) {
    EXPECT_LE(norm(a.force[i] - b.force[i]), 1e-12 * norm(a.force[i]));
    EXPECT_EQ(norm(a.torque[i]), 0.0);
  }
  EXPECT_NEAR(a.energy, b.energy, 1e-12 * std::abs(a.energy));
}

TEST(Coulomb, ExternalFieldAndIsolatedSphere) {
  SolverOptions o;
  o.solver = "coulomb";
  auto s = make_solver(o);
  expect_uniform_field_sphere(*s, 1.0, 2 * kQ0, Vec3{1e5, 0, -3e4}, 1e-14, 1e-14);
  expect_net_charges_far_field(*s, 1, 1, 2.0, 1e-14);
}
