// Analytic checks of the JKR contact law, docs/model.md §A.4 items 1-4, and the delta <-> a round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "agglo/dem/contact/alpha_damping.hpp"
#include "agglo/dem/jkr.hpp"

using agglo::dem::JkrPair;

namespace {

JkrPair seed_pair() {
  // r = 10 um spheres: R = 5 um, E* = E / (2 (1 - nu^2)) with E = 1 GPa, nu = 0.33; gamma = 10 mJ/m^2.
  return JkrPair::make(5e-6, 1e9 / (2.0 * (1.0 - 0.33 * 0.33)), 0.01);
}

TEST(Jkr, EquilibriumPoint) {
  auto p = seed_pair();
  EXPECT_NEAR(p.force_of_a(p.a0), 0.0, 1e-14 * p.Fc);
  EXPECT_NEAR(p.delta_of_a(p.a0) / p.deltaC, 1.21141, 5e-6);
  EXPECT_NEAR(p.delta_equilibrium(), p.delta_of_a(p.a0), 1e-12 * p.deltaC);
  // Stiffness dF/d(delta) at a0 by central differences along the curve.
  double h = 1e-6 * p.deltaC, d0 = p.delta_equilibrium();
  double k = (p.force_of_a(p.a_of_delta(d0 + h)) - p.force_of_a(p.a_of_delta(d0 - h))) / (2 * h);
  // Closed form: dF/d(delta) = (dF/da)/(d(delta)/da) = (6 F_C/a0) / (5 a0 / (3 R)) = 1.8 / 6^(1/3) F_C/delta_C
  // = 0.990578 F_C/delta_C. an earlier version of the specification quoted 0.99050 (truncated to 4 digits; 8e-5 below the exact value).
  EXPECT_NEAR(k / (p.Fc / p.deltaC), 1.8 / std::cbrt(6.0), 1e-8);
  EXPECT_NEAR(k / (p.Fc / p.deltaC), 0.99050, 1e-4);
}

TEST(Jkr, PullOffMinimum) {
  auto p = seed_pair();
  double a_min = std::pow(2.0, -2.0 / 3.0) * p.a0;
  EXPECT_NEAR(p.force_of_a(a_min) / p.Fc, -1.0, 1e-12);
  EXPECT_NEAR(p.delta_of_a(a_min) / p.deltaC, -0.48075, 5e-6);
  // It is the minimum over the stable branch.
  double fmin = 0.0;
  for (double d = -p.deltaC; d <= 2 * p.deltaC; d += 1e-4 * p.deltaC) fmin = std::min(fmin, p.force_of_a(p.a_of_delta(d)));
  EXPECT_NEAR(fmin / p.Fc, -1.0, 1e-6);
}

TEST(Jkr, SnapInAndBreak) {
  auto p = seed_pair();
  double a_in = p.a_of_delta(0.0);
  EXPECT_NEAR(a_in / p.a0, 0.763143, 1e-6);
  EXPECT_NEAR(p.force_of_a(a_in) / p.Fc, -8.0 / 9.0, 1e-6);
  double a_br = p.a_of_delta(-p.deltaC);
  EXPECT_NEAR(a_br / p.a0, 0.302853, 1e-6);
  EXPECT_NEAR(p.force_of_a(a_br) / p.Fc, -5.0 / 9.0, 1e-6);
}

TEST(Jkr, SeparationWork) {
  // W = int_{-delta_C}^{0} |F| d(delta), integrated along a (delta(a) is smooth in a) by Simpson.
  auto p = seed_pair();
  double a1 = p.a_of_delta(-p.deltaC), a2 = p.a_of_delta(0.0);
  const int n = 20000;
  double h = (a2 - a1) / n, w = 0.0;
  auto integrand = [&](double a) {
    double e = 1e-9 * p.a0;
    double dd = (p.delta_of_a(a + e) - p.delta_of_a(a - e)) / (2 * e);
    return std::abs(p.force_of_a(a)) * dd;
  };
  for (int k = 0; k <= n; ++k) w += integrand(a1 + k * h) * (k == 0 || k == n ? 1 : (k % 2 ? 4 : 2));
  w *= h / 3.0;
  EXPECT_NEAR(w / (p.Fc * p.deltaC), 0.935503, 2e-6);
}

TEST(Jkr, InversionRoundTrip) {
  for (double R : {1e-7, 5e-6, 1e-3})
    for (double gamma : {1e-3, 0.01, 0.1}) {
      auto p = JkrPair::make(R, 5e8, gamma);
      for (double x = -0.99999; x < 20.0; x += 0.01737) {
        double d = x * p.deltaC;
        double a = p.a_of_delta(d);
        EXPECT_NEAR(p.delta_of_a(a), d, 1e-12 * p.deltaC) << "R=" << R << " gamma=" << gamma << " x=" << x;
        // Warm start from a neighbouring value gives the same root.
        double a2 = p.a_of_delta(d, a * 1.01);
        EXPECT_NEAR(a2, a, 1e-12 * p.a0);
      }
    }
}

// a_of_delta_lanes (the one-thread pair loop's radii, eight at a time) gives a_of_delta's bits in every lane:
// lanes of different pairs, at or below the turning point delta = -delta_C (no Newton), cold starts, warm
// starts on either side of the root and near the turning point (slow convergence), mixed in one call so that
// lanes stop at different iterations.
TEST(Jkr, LanesBitIdenticalToAOfDelta) {
  const JkrPair pairs[2] = {seed_pair(), JkrPair::make(2.5e-6, 3e8, 0.03)};
  constexpr int L = 8;
  unsigned seed = 12345u;
  auto uniform = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) * (1.0 / 16777216.0);
  };
  int compared = 0;
  for (int call = 0; call < 400; ++call) {
    const JkrPair* jkr[L];
    double delta[L], guess[L], a[L];
    double* out[L];
    for (int l = 0; l < L; ++l) {
      jkr[l] = &pairs[(call + l) % 2];
      const double x = -1.3 + 21.3 * uniform();  // delta / delta_C, also below the turning point -1
      delta[l] = (l == 0 && call % 4 == 0 ? -0.9999 : x) * jkr[l]->deltaC;  // -0.9999: slow Newton
      const double exact = jkr[l]->a_of_delta(delta[l]);
      const int kind = (call + 3 * l) % 4;  // none, left of the root, right of it, far off
      guess[l] = kind == 0 ? 0.0 : exact * (kind == 1 ? 0.999 : kind == 2 ? 1.001 : 1.0 + 2.0 * uniform());
      a[l] = guess[l];
      out[l] = &a[l];
    }
    agglo::dem::a_of_delta_lanes<L>(jkr, delta, out);
    for (int l = 0; l < L; ++l) {
      const double ref = jkr[l]->a_of_delta(delta[l], guess[l]);
      ASSERT_EQ(std::memcmp(&a[l], &ref, sizeof ref), 0)
          << "call " << call << " lane " << l << ": " << a[l] << " vs " << ref;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 400 * L);
}

TEST(Jkr, DampingCoefficient) {
  // alpha(1) ~ 0 (no damping for perfectly elastic contacts), alpha decreasing in e.
  EXPECT_NEAR(agglo::dem::contact::damping_alpha(1.0), 0.0, 1e-3);
  for (double e = 0.1; e < 0.95; e += 0.05)
    EXPECT_GT(agglo::dem::contact::damping_alpha(e), agglo::dem::contact::damping_alpha(e + 0.05));
}

}  // namespace
