// The shared restarted GMRES (agglo/electrostatics/gmres.hpp) against Eigen's dense LU solve.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <omp.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "agglo/electrostatics/gmres.hpp"

using namespace agglo::es;

namespace {

constexpr int kN = 50;

// Random nonsymmetric, well-conditioned matrix: 2 I + R / sqrt(n), R uniform in [-1, 1]; the
// eigenvalues lie in a disc of radius ~0.6 about 2, so GMRES converges geometrically.
struct System {
  Eigen::MatrixXd A;
  Eigen::VectorXd b, x;  // x: dense solution
  std::vector<double> bv, weights;
};

System make_system(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), wd(0.5, 2.0);
  System s;
  s.A = Eigen::MatrixXd::Identity(kN, kN) * 2.0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) s.A(i, j) += u(rng) / std::sqrt(double(kN));
  s.b.resize(kN);
  for (int i = 0; i < kN; ++i) s.b(i) = u(rng);
  s.x = s.A.partialPivLu().solve(s.b);
  s.bv.assign(s.b.data(), s.b.data() + kN);
  for (int i = 0; i < kN; ++i) s.weights.push_back(wd(rng));
  return s;
}

LinearOperator op_of(const Eigen::MatrixXd& A) {
  return [&A](std::span<const double> x, std::span<double> y) {
    Eigen::Map<Eigen::VectorXd>(y.data(), kN) = A * Eigen::Map<const Eigen::VectorXd>(x.data(), kN);
  };
}

double max_diff(const std::vector<double>& a, const Eigen::VectorXd& b) {
  double m = 0.0;
  for (int i = 0; i < kN; ++i) m = std::max(m, std::abs(a[i] - b(i)));
  return m;
}

// ||b - A x||_w / ||b||_w (Euclidean for empty w).
double rel_residual(const System& s, const std::vector<double>& x, const std::vector<double>& w) {
  const Eigen::VectorXd r = s.b - s.A * Eigen::Map<const Eigen::VectorXd>(x.data(), kN);
  double rn = 0.0, bn = 0.0;
  for (int i = 0; i < kN; ++i) {
    const double wi = w.empty() ? 1.0 : w[i];
    rn += wi * r(i) * r(i);
    bn += wi * s.b(i) * s.b(i);
  }
  return std::sqrt(rn / bn);
}

}  // namespace

TEST(Gmres, EuclideanRestartedMatchesDenseSolve) {
  const System s = make_system(1);
  std::vector<double> x(kN, 0.0);
  const GmresOptions opt{1e-12, 500, 5, true};
  const GmresResult r = gmres(op_of(s.A), s.bv, x, {}, opt);
  EXPECT_TRUE(r.converged);
  EXPECT_GT(r.iterations, opt.restart);  // several cycles were needed
  EXPECT_LE(r.residual, 1e-12);
  EXPECT_NEAR(r.residual, rel_residual(s, x, {}), 1e-14);
  // one explicit residual per cycle plus the final re-check
  const int cycles = (r.iterations + opt.restart - 1) / opt.restart;
  EXPECT_EQ(r.matvecs, r.iterations + cycles + 1);
  EXPECT_LT(max_diff(x, s.x), 1e-10);
}

TEST(Gmres, WeightedRestartedMatchesDenseSolve) {
  const System s = make_system(2);
  std::vector<double> x(kN, 0.0);
  const GmresOptions opt{1e-12, 500, 7, true};
  const GmresResult r = gmres(op_of(s.A), s.bv, x, s.weights, opt);
  EXPECT_TRUE(r.converged);
  EXPECT_GT(r.iterations, opt.restart);
  EXPECT_LE(r.residual, 1e-12);
  // the reported residual is the true one in the weighted norm
  EXPECT_NEAR(r.residual, rel_residual(s, x, s.weights), 1e-14);
  EXPECT_LT(max_diff(x, s.x), 1e-10);
}

TEST(Gmres, UnitWeightsAgreeWithEuclidean) {
  const System s = make_system(3);
  std::vector<double> xe(kN, 0.0), xw(kN, 0.0), ones(kN, 1.0);
  const GmresOptions opt{1e-10, 500, 10, true};
  const GmresResult re = gmres(op_of(s.A), s.bv, xe, {}, opt);
  const GmresResult rw = gmres(op_of(s.A), s.bv, xw, ones, opt);
  EXPECT_EQ(re.iterations, rw.iterations);
  for (int i = 0; i < kN; ++i) EXPECT_NEAR(xe[i], xw[i], 1e-13);
}

TEST(Gmres, WarmStartFromExactSolutionTakesNoIterations) {
  const System s = make_system(4);
  for (bool weighted : {false, true}) {
    std::vector<double> x(s.x.data(), s.x.data() + kN);
    const GmresResult r =
        gmres(op_of(s.A), s.bv, x, weighted ? std::span<const double>(s.weights) : std::span<const double>{},
              GmresOptions{1e-10, 100, 20, true});
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(r.matvecs, 1);  // only the initial residual
    EXPECT_LE(r.residual, 1e-10);
    for (int i = 0; i < kN; ++i) EXPECT_EQ(x[i], s.x(i));  // untouched
  }
}

TEST(Gmres, ReportsNonConvergence) {
  const System s = make_system(5);
  for (bool recheck : {true, false}) {
    std::vector<double> x(kN, 0.0);
    const GmresResult r = gmres(op_of(s.A), s.bv, x, s.weights, GmresOptions{1e-14, 3, 20, recheck});
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.iterations, 3);
    EXPECT_EQ(r.matvecs, recheck ? 5 : 4);
    EXPECT_GT(r.residual, 1e-14);
    EXPECT_TRUE(std::isfinite(r.residual));
    EXPECT_LT(r.residual, 1.0);  // but it made progress
  }
}

TEST(Gmres, WithoutRecheckReturnsTheEstimateAndSavesOneMatvec) {
  const System s = make_system(6);
  std::vector<double> x1(kN, 0.0), x2(kN, 0.0);
  const GmresResult r1 = gmres(op_of(s.A), s.bv, x1, {}, GmresOptions{1e-10, 500, 60, true});
  const GmresResult r2 = gmres(op_of(s.A), s.bv, x2, {}, GmresOptions{1e-10, 500, 60, false});
  ASSERT_TRUE(r1.converged);
  ASSERT_TRUE(r2.converged);
  EXPECT_EQ(r1.iterations, r2.iterations);  // single cycle: same Krylov steps, same x
  EXPECT_EQ(r1.matvecs, r1.iterations + 2);
  EXPECT_EQ(r2.matvecs, r2.iterations + 1);
  for (int i = 0; i < kN; ++i) EXPECT_EQ(x1[i], x2[i]);
  EXPECT_NEAR(r2.residual, rel_residual(s, x2, {}), 1e-12);  // estimate ~ true residual
}

TEST(Gmres, WorkspaceReuseIsAllocationFreeAndReproducible) {
  const System s = make_system(7);
  GmresWorkspace ws;
  const GmresOptions opt{1e-12, 500, 8, true};
  std::vector<double> x0(kN, 0.0), x1(kN, 0.0), x2(kN, 0.0);
  const GmresResult r0 = gmres(op_of(s.A), s.bv, x0, s.weights, opt);  // temporary workspace
  const GmresResult r1 = gmres(op_of(s.A), s.bv, x1, s.weights, opt, &ws);
  const double* basis = ws.V.data();
  const double* hess = ws.H.data();
  const double* ybuf = ws.y.data();
  const GmresResult r2 = gmres(op_of(s.A), s.bv, x2, s.weights, opt, &ws);
  EXPECT_EQ(ws.V.data(), basis);
  EXPECT_EQ(ws.H.data(), hess);
  EXPECT_EQ(ws.y.data(), ybuf);
  EXPECT_EQ(r0.iterations, r1.iterations);
  EXPECT_EQ(r1.iterations, r2.iterations);
  EXPECT_EQ(r1.residual, r2.residual);
  for (int i = 0; i < kN; ++i) {
    EXPECT_EQ(x0[i], x1[i]);
    EXPECT_EQ(x1[i], x2[i]);
  }
}

TEST(Gmres, ZeroRightHandSideAndBadSizes) {
  const System s = make_system(8);
  std::vector<double> zero(kN, 0.0), x(kN, 1.0);
  const GmresResult r = gmres(op_of(s.A), zero, x, {}, GmresOptions{});
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.matvecs, 0);
  for (double v : x) EXPECT_EQ(v, 0.0);
  std::vector<double> short_x(kN - 1, 0.0), short_w(kN - 1, 1.0);
  EXPECT_THROW(gmres(op_of(s.A), s.bv, short_x, {}, GmresOptions{}), std::invalid_argument);
  EXPECT_THROW(gmres(op_of(s.A), s.bv, x, short_w, GmresOptions{}), std::invalid_argument);
}

// Vectors of 3e5 numbers (above the length from which gmres.cpp sums its Euclidean inner products in
// parallel blocks): the solution must have the same bits on one and two threads (the blocks and their
// order depend on the length only; a reduction that followed the thread count would change the last
// bits), and its true residual must meet the tolerance. The operator is tridiagonal,
// y_j = 2 x_j + c_j x_(j-1) - c_(j+1) x_(j+1) with c_j = 0.4 sin(j) (eigenvalues within 0.8 of 2).
TEST(Gmres, LongEuclideanSolveHasTheSameBitsOnOneAndTwoThreads) {
  const std::size_t n = 300000;
  std::vector<double> c(n + 1), b(n);
  for (std::size_t j = 0; j <= n; ++j) c[j] = 0.4 * std::sin(double(j));
  for (std::size_t j = 0; j < n; ++j) b[j] = std::cos(0.001 * double(j)) + 0.1 * std::sin(7.0 * double(j));
  const LinearOperator A = [&c, n](std::span<const double> x, std::span<double> y) {
    for (std::size_t j = 0; j < n; ++j)
      y[j] = 2.0 * x[j] + (j > 0 ? c[j] * x[j - 1] : 0.0) - (j + 1 < n ? c[j + 1] * x[j + 1] : 0.0);
  };
  const int saved = omp_get_max_threads();
  std::vector<std::vector<double>> x(2, std::vector<double>(n, 0.0));
  GmresResult r[2];
  for (int t = 0; t < 2; ++t) {
    omp_set_num_threads(t + 1);
    r[t] = gmres(A, b, x[t], {}, GmresOptions{1e-10, 200, 10, true});
  }
  omp_set_num_threads(saved);
  ASSERT_TRUE(r[0].converged);
  EXPECT_GT(r[0].iterations, 10);  // more than one restart cycle
  EXPECT_EQ(r[0].iterations, r[1].iterations);
  EXPECT_EQ(r[0].residual, r[1].residual);
  std::size_t differ = 0;
  for (std::size_t j = 0; j < n; ++j) differ += x[0][j] != x[1][j];
  EXPECT_EQ(differ, 0u);
  std::vector<double> ax(n);
  A(x[0], ax);
  double rn = 0.0, bn = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    rn += (b[j] - ax[j]) * (b[j] - ax[j]);
    bn += b[j] * b[j];
  }
  EXPECT_LE(std::sqrt(rn / bn), 1e-10);
}
