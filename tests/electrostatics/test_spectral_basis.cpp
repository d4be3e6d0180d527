// Unit checks of the spectral building blocks: solid-harmonic gradient and rotation generator
// against finite differences, frame rotations against direct evaluation, and the axial
// multipole-to-local translation against the direct multipole sum.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "agglo/electrostatics/spectral/harmonics.hpp"
#include "agglo/electrostatics/spectral/rotation.hpp"
#include "agglo/electrostatics/spectral/translation.hpp"

using namespace agglo;
using namespace agglo::es;

namespace {

std::vector<double> random_coeffs(int L, std::mt19937& g) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> c(sh::ncoef(L));
  for (auto& x : c) x = u(g);
  return c;
}

double eval_reg(int L, const std::vector<double>& a, const Vec3& x) {
  std::vector<double> y(sh::ncoef(L));
  sh::eval_regular(L, x, y.data());
  double s = 0;
  for (int k = 0; k < sh::ncoef(L); ++k) s += a[k] * y[k];
  return s;
}

double eval_irr(int L, const std::vector<double>& a, const Vec3& x) {
  std::vector<double> y(sh::ncoef(L));
  sh::eval_irregular(L, x, y.data());
  double s = 0;
  for (int k = 0; k < sh::ncoef(L); ++k) s += a[k] * y[k];
  return s;
}

Vec3 fd_grad(int L, const std::vector<double>& a, const Vec3& x) {
  const double h = 1e-5;
  Vec3 g;
  for (int d = 0; d < 3; ++d) {
    Vec3 xp = x, xm = x;
    xp[d] += h;
    xm[d] -= h;
    g[d] = (eval_reg(L, a, xp) - eval_reg(L, a, xm)) / (2 * h);
  }
  return g;
}

}  // namespace

TEST(SpectralBasis, OrthogonalityWeights) {
  // (1/4pi) \int Y_lm^2 dOmega = norm_weight(l, m): check by Gauss-like midpoint quadrature.
  const int L = 6, nt = 400, np = 64;
  std::vector<double> acc(sh::ncoef(L), 0.0), y(sh::ncoef(L));
  for (int i = 0; i < nt; ++i) {
    double ct = -1 + (i + 0.5) * 2.0 / nt;
    double st = std::sqrt(1 - ct * ct);
    for (int k = 0; k < np; ++k) {
      double ph = 2 * M_PI * k / np;
      sh::eval_surface(L, {st * std::cos(ph), st * std::sin(ph), ct}, y.data());
      for (int q = 0; q < sh::ncoef(L); ++q) acc[q] += y[q] * y[q] * (2.0 / nt) * (2 * M_PI / np) / (4 * M_PI);
    }
  }
  for (int l = 0; l <= L; ++l)
    for (int m = -l; m <= l; ++m) EXPECT_NEAR(acc[sh::idx(l, m)], sh::norm_weight(l, m), 2e-4) << l << " " << m;
}

TEST(SpectralBasis, GradientMatchesFiniteDifferences) {
  std::mt19937 g(1);
  const int L = 9;
  auto a = random_coeffs(L, g);
  std::vector<double> gx(sh::ncoef(L)), gy(sh::ncoef(L)), gz(sh::ncoef(L));
  sh::gradient(L, a.data(), gx.data(), gy.data(), gz.data());
  for (Vec3 x : {Vec3{0.3, -0.2, 0.5}, Vec3{-0.7, 0.1, -0.2}, Vec3{0.0, 0.0, 0.8}}) {
    Vec3 fd = fd_grad(L, a, x);
    EXPECT_NEAR(eval_reg(L, gx, x), fd.x, 1e-7);
    EXPECT_NEAR(eval_reg(L, gy, x), fd.y, 1e-7);
    EXPECT_NEAR(eval_reg(L, gz, x), fd.z, 1e-7);
  }
}

TEST(SpectralBasis, RotationGeneratorIsRCrossGrad) {
  std::mt19937 g(2);
  const int L = 8;
  auto a = random_coeffs(L, g);
  std::vector<double> rx(sh::ncoef(L)), ry(sh::ncoef(L)), rz(sh::ncoef(L));
  sh::rotation_generator(L, a.data(), rx.data(), ry.data(), rz.data());
  for (Vec3 x : {Vec3{0.3, -0.2, 0.5}, Vec3{-0.7, 0.1, -0.2}}) {
    Vec3 expect = cross(x, fd_grad(L, a, x));
    EXPECT_NEAR(eval_reg(L, rx, x), expect.x, 1e-7);
    EXPECT_NEAR(eval_reg(L, ry, x), expect.y, 1e-7);
    EXPECT_NEAR(eval_reg(L, rz, x), expect.z, 1e-7);
  }
}

TEST(SpectralBasis, FrameRotationMapsDirectionToZ) {
  std::mt19937 g(3);
  const int L = 30;
  for (Vec3 e : {Vec3{0.3, -0.5, 0.8}, Vec3{-1, 0.2, -0.1}, Vec3{0, 0, 1}, Vec3{0, 0, -2}, Vec3{1e-9, 0, -1}}) {
    auto c = random_coeffs(L, g);
    sh::FrameRotation R;
    R.build(e, L);
    std::vector<double> cp(sh::ncoef(L)), back(sh::ncoef(L));
    R.to_frame(L, c.data(), cp.data());
    // Q = R_y(-b) R_z(-a): build it explicitly and compare f(x) with f'(Q x).
    double a = std::atan2(e.y, e.x), b = std::atan2(std::hypot(e.x, e.y), e.z);
    if (std::hypot(e.x, e.y) == 0) a = 0;
    auto Q = [&](Vec3 x) {
      Vec3 y{x.x * std::cos(a) + x.y * std::sin(a), -x.x * std::sin(a) + x.y * std::cos(a), x.z};
      return Vec3{y.x * std::cos(b) - y.z * std::sin(b), y.y, y.x * std::sin(b) + y.z * std::cos(b)};
    };
    Vec3 qe = Q(e / norm(e));
    EXPECT_NEAR(qe.z, 1.0, 1e-12);
    for (Vec3 x : {Vec3{0.3, 0.4, -0.2}, Vec3{-0.5, 0.1, 0.6}}) {
      double f = eval_reg(L, c, x), fp = eval_reg(L, cp, Q(x));
      EXPECT_NEAR(f, fp, 1e-10 * (1 + std::abs(f)));
    }
    R.from_frame(L, cp.data(), back.data());
    for (int k = 0; k < sh::ncoef(L); ++k) EXPECT_NEAR(back[k], c[k], 1e-11);
    // fused two-vector versions agree with the single ones (all orders kept)
    auto c2 = random_coeffs(L, g);
    std::vector<double> f1(sh::ncoef(L)), f2(sh::ncoef(L)), g1(sh::ncoef(L), 0.0), g2(sh::ncoef(L), 0.0), r2(sh::ncoef(L));
    R.to_frame2(L, L, c.data(), c2.data(), f1.data(), f2.data());
    R.to_frame(L, c2.data(), r2.data());
    for (int k = 0; k < sh::ncoef(L); ++k) {
      EXPECT_NEAR(f1[k], cp[k], 1e-12);
      EXPECT_NEAR(f2[k], r2[k], 1e-12);
    }
    R.from_frame2(L, L, f1.data(), f2.data(), g1.data(), g2.data());
    for (int k = 0; k < sh::ncoef(L); ++k) {
      EXPECT_NEAR(g1[k], c[k], 1e-11);
      EXPECT_NEAR(g2[k], c2[k], 1e-11);
    }
  }
}

TEST(SpectralBasis, AxialTranslationMatchesDirectSum) {
  std::mt19937 g(4);
  const int Ls = 6, L = 40;
  auto B = random_coeffs(Ls, g);
  std::vector<double> Bfull(sh::ncoef(L), 0.0);
  for (int k = 0; k < sh::ncoef(Ls); ++k) Bfull[k] = B[k];
  sh::AxialTranslation T;
  T.prepare(L);
  for (int sign : {+1, -1}) {
    const double t = 2.0;
    // unscaled: u = 1, v = 1 with radii 1 means alpha = A, beta = B/t... use radii a=b=1: u=v=1/t.
    const double a = 1.0, b = 1.0;
    std::vector<double> Bs(sh::ncoef(L)), A(sh::ncoef(L), 0.0);
    for (int l = 0; l <= L; ++l)
      for (int m = -l; m <= l; ++m) Bs[sh::idx(l, m)] = Bfull[sh::idx(l, m)] / std::pow(b, l + 1);
    T.apply(L, L, a / t, b / t, sign, Bs.data(), A.data());
    Vec3 c{0, 0, sign * t};
    for (Vec3 x : {Vec3{0.2, -0.1, 0.15}, Vec3{-0.1, 0.25, -0.2}}) {
      double direct = eval_irr(Ls, B, x - c);
      double local = eval_reg(L, A, x);  // a = 1: alpha = A
      EXPECT_NEAR(local, direct, 1e-12 * std::abs(direct) + 1e-14) << sign;
    }
  }
}
