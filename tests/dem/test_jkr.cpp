// Analytic checks of the JKR contact law, docs/model.md §A.4 items 1-4, and the delta <-> a round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

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

// The exact root s of 2 s^4 - 4/3 s = t for a double t >= -s_min, by bisection in long double on the form
// without the double root, (s - m) (2 s^2 + 4 m s + 6 m^2)^(1/2) = (t + m)^(1/2) (independent of the table's
// Newton on the same form and of a_of_delta's Newton on f).
long double exact_root(double t) {
  const long double m = 1.0L / std::cbrt(6.0L);
  const long double w = std::sqrt(std::max(static_cast<long double>(t) + m, 0.0L));
  long double lo = m, hi = m + 1.0L + w;
  for (int it = 0; it < 160; ++it) {
    const long double mid = 0.5L * (lo + hi);
    ((mid - m) * std::sqrt(2.0L * mid * mid + 4.0L * m * mid + 6.0L * m * m) > w ? hi : lo) = mid;
  }
  return 0.5L * (lo + hi);
}

// The fast path's root (jkr_root_fast: table + one Halley step, no warm start, no convergence test) against the
// exact root over the whole range of an engaged contact: from the turning point t = -s_min (delta = -delta_C,
// the pull-off branch of break_rule "marshall") through fresh contacts (delta >= 0) to beyond the table
// (t >= 63.4, the Newton fallback). Bounds per distance tau = t + s_min from the turning point, where the root
// is ill-conditioned (ds/dt = 1/f'(s) -> infinity); a_of_delta's own error is checked against the same bounds
// (the exact root is right; and the fast root is no worse than the reference twin's), and F_ne from s against
// force_of_a(s^2 a0).
TEST(Jkr, FastRootAgainstExactRoot) {
  const double m = agglo::dem::kJkrSMin;
  struct Bin {
    double tau_lo, tau_hi, bound;
    double fast = 0.0, ref = 0.0;
    int n = 0;
  };
  Bin bins[] = {{0.0, 1e-6, 5e-9}, {1e-6, 1e-2, 1e-13}, {1e-2, 80.0, 1e-15}};
  std::vector<double> taus;
  for (double x = -16.0; x < -2.0; x += 0.01) taus.push_back(std::pow(10.0, x));
  for (double x = 1e-2; x < 80.0; x += 1.37e-3) taus.push_back(x);
  const JkrPair p = seed_pair();
  for (double tau : taus) {
    const double t = -m + tau;
    const long double ex = exact_root(t);
    const double fast = agglo::dem::jkr_root_fast(t);
    const double ref = std::sqrt(p.a_of_delta(t / p.t_per_delta) / p.a0);  // the reference (cold start)
    for (Bin& b : bins)
      if (tau >= b.tau_lo && tau < b.tau_hi) {
        b.fast = std::max(b.fast, static_cast<double>(std::abs(fast - ex) / ex));
        b.ref = std::max(b.ref, static_cast<double>(std::abs(ref - ex) / ex));
        ++b.n;
      }
    const double f_fast = agglo::dem::jkr_force_of_root(p, fast), f_ref = p.force_of_a(fast * fast * p.a0);
    ASSERT_NEAR(f_fast, f_ref, 1e-14 * (std::abs(f_ref) + p.Fc)) << "t " << t;
  }
  for (const Bin& b : bins) {
    EXPECT_GT(b.n, 100);
    EXPECT_LE(b.fast, b.bound) << "tau in [" << b.tau_lo << ", " << b.tau_hi << "): " << b.n << " points";
    EXPECT_LE(b.ref, b.bound) << "reference, tau in [" << b.tau_lo << ", " << b.tau_hi << ")";
    std::printf("tau in [%g, %g): %d points, max relative error fast %.2e, reference %.2e\n", b.tau_lo, b.tau_hi, b.n,
                b.fast, b.ref);
  }
  // The table's own error (no Halley step) is far above the bounds: the polish is doing the work (control).
  double table_err = 0.0;
  for (double tau : taus) {
    if (tau >= 63.0) continue;
    const double x = std::sqrt(tau) * (agglo::dem::kJkrTableCells / agglo::dem::kJkrTableW);
    const int cell = static_cast<int>(x);
    const double u = x - cell;
    const double* c = agglo::dem::kJkrRootTable.c[cell];
    const double s0 = c[0] + u * (c[1] + u * (c[2] + u * c[3]));
    table_err = std::max(table_err, static_cast<double>(std::abs(s0 - exact_root(-m + tau)) / exact_root(-m + tau)));
  }
  EXPECT_GT(table_err, 1e-10);
  EXPECT_LT(table_err, 3e-8);
}

TEST(Jkr, DampingCoefficient) {
  // alpha(1) ~ 0 (no damping for perfectly elastic contacts), alpha decreasing in e.
  EXPECT_NEAR(agglo::dem::contact::damping_alpha(1.0), 0.0, 1e-3);
  for (double e = 0.1; e < 0.95; e += 0.05)
    EXPECT_GT(agglo::dem::contact::damping_alpha(e), agglo::dem::contact::damping_alpha(e + 0.05));
}

}  // namespace
