// The sectional solver against the closed-form solutions of the Smoluchowski equation for an
// exponential start n(v, 0) = (N0/v0) e^(-v/v0) (cases/partmc_constant.toml, cases/partmc_additive.toml):
// N(t) within 1e-3 and the size distribution (the exact n(v, t) projected onto the pivots the way the
// initial state is, initial.hpp) within 1e-2 relative L2.
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "agglo/sectional/initial.hpp"
#include "helpers.hpp"

using namespace agglo::sectional;

namespace {

// Constant kernel K (pair rate K N^2 / 2), tau = K N0 t. The solution stays exponential
// (Friedlander, Smoke, Dust and Haze, ch. 7; Seinfeld & Pandis, ch. 13):
//   N(t) = 2 N0 / (2 + tau),  n(v, t) = (N/vbar) e^(-v/vbar) with vbar = N0 v0 / N = v0 (2 + tau)/2,
// so the number falls as the mean volume grows and the total volume N0 v0 stays.
agglo::acoustics::PopulationSpec constant_kernel_solution(double n0, double v0, double tau) {
  agglo::acoustics::PopulationSpec p;
  p.distribution = agglo::acoustics::Distribution::exponential;
  p.number_concentration = 2.0 * n0 / (2.0 + tau);
  p.mean_volume = v0 * (2.0 + tau) / 2.0;
  return p;
}

// e^(-x) I_1(x) for x >= 0 (Bessel function of the first kind, modified; its large-x expansion above 700).
double scaled_bessel_i1(double x) {
  if (x < 700.0) return std::cyl_bessel_i(1.0, x) * std::exp(-x);
  const double y = 1.0 / (8.0 * x);
  return (1.0 - 3.0 * y - 7.5 * y * y - 52.5 * y * y * y) / std::sqrt(2.0 * M_PI * x);
}

// Additive (Golovin) kernel B (v + v'), tau = B N0 v0 t, T = 1 - e^(-tau). With an exponential start the
// number falls as N = N0 e^(-tau) (dN/dt = -B N0 v0 N, the total volume being constant) and
//   n(v, t) = N0 (1 - T) / (v sqrt(T)) e^(-(1 + T) v/v0) I_1(2 sqrt(T) v/v0)
// (Golovin 1963; Seinfeld & Pandis, ch. 13). For small T, I_1(z) ~ z/2 gives back the start.
double golovin(double n0, double v0, double tau, double v) {
  const double T = -std::expm1(-tau), s = std::sqrt(T), z = 2.0 * s * v / v0;
  return n0 * (1.0 - T) / (v * s) * std::exp(-(1.0 + T) * v / v0 + z) * scaled_bessel_i1(z);
}

// Number and volume of n on [a, b] by 8-point Gauss-Legendre, then split onto the pivots (initial.hpp).
template <class F>
std::vector<double> project_density(const Grid& g, F n) {
  static const std::array<double, 4> xs = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                           0.9602898564975363};
  static const std::array<double, 4> ws = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                           0.1012285362903763};
  std::vector<double> out(g.size(), 0.0);
  for (std::size_t i = 0; i + 1 < g.size(); ++i) {
    const double a = g.x[i], b = g.x[i + 1], c = 0.5 * (a + b), h = 0.5 * (b - a);
    double num = 0.0, vol = 0.0;
    for (std::size_t q = 0; q < xs.size(); ++q)
      for (double sgn : {-1.0, 1.0}) {
        const double v = c + sgn * h * xs[q], f = ws[q] * h * n(v);
        num += f;
        vol += f * v;
      }
    const double up = (vol - a * num) / (b - a);
    out[i + 1] += up;
    out[i] += num - up;
  }
  return out;
}

}  // namespace

TEST(SectionalClosedForm, ConstantKernelNumberAndDistribution) {
  const double K = 2.0833333e-11, n0 = 4.8e10, v0 = M_PI / 6 * 8e-15;
  SectionalSolver s(test::shipped_case("partmc_constant"));
  for (double t : {4.5, 9.0, 18.0}) {
    s.advance_to(t);
    const double tau = K * n0 * t;
    EXPECT_LT(std::abs(s.number() / (2.0 * n0 / (2.0 + tau)) - 1.0), 1e-3) << "t = " << t;
    const auto exact = project(s.grid(), {constant_kernel_solution(n0, v0, tau)}).n;
    EXPECT_LT(test::relative_l2(s.n(), exact), 1e-2) << "t = " << t;
    EXPECT_LT(test::relative_l2(s.n(), exact, s.grid().x), 1e-2) << "t = " << t;  // volume-weighted
    RecordProperty("l2_number_t" + std::to_string(static_cast<int>(t)), std::to_string(test::relative_l2(s.n(), exact)));
  }
  EXPECT_NEAR(s.number() / n0, 0.1, 1e-4);  // the benchmark's end point N/N0 = 0.1
  EXPECT_NEAR(s.volume(), n0 * v0, 1e-9 * n0 * v0);
}

TEST(SectionalClosedForm, AdditiveKernelNumberAndDistribution) {
  const double B = 1000.0, n0 = 1e9, v0 = M_PI / 6 * 8e-15;
  SectionalSolver s(test::shipped_case("partmc_additive"));
  for (double t : {150.0, 300.0, 600.0}) {
    s.advance_to(t);
    const double tau = B * n0 * v0 * t;
    EXPECT_LT(std::abs(s.number() / (n0 * std::exp(-tau)) - 1.0), 1e-3) << "t = " << t;
    const auto exact = project_density(s.grid(), [&](double v) { return golovin(n0, v0, tau, v); });
    EXPECT_LT(test::relative_l2(s.n(), exact), 1e-2) << "t = " << t;
    RecordProperty("l2_number_t" + std::to_string(static_cast<int>(t)), std::to_string(test::relative_l2(s.n(), exact)));
    // The volume-weighted distribution carries the fixed pivot's known excess at the large sizes
    // (measured 1.3 %, 2.7 %, 6.3 % at these times with 40 pivots per decade; docs/sectional.md).
  }
  // The exponential integrator is not exactly volume-conserving; at the default tolerance 1e-6 the
  // drift over the run is 2.3e-5 (docs/sectional.md).
  EXPECT_NEAR(s.volume(), n0 * v0, 1e-4 * n0 * v0);
}

TEST(SectionalClosedForm, GolovinFormulaKeepsVolume) {
  // The closed form itself: total volume N0 v0 at every time (guards the formula used above).
  const double n0 = 1e9, v0 = M_PI / 6 * 8e-15;
  const Grid g = Grid::geometric(1e-7, 1e-2, 60);
  for (double tau : {0.5, 2.5}) {
    const auto p = project_density(g, [&](double v) { return golovin(n0, v0, tau, v); });
    double n = 0, vol = 0;
    for (std::size_t i = 0; i < g.size(); ++i) {
      n += p[i];
      vol += p[i] * g.x[i];
    }
    EXPECT_NEAR(vol / (n0 * v0), 1.0, 1e-6);
    EXPECT_NEAR(n / (n0 * std::exp(-tau)), 1.0, 1e-6);
  }
}
