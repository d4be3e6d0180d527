#include "two_sphere_reference.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace agglo::es::testref {

namespace {

constexpr double kEps0 = 8.8541878128e-12;
constexpr double kPi = 3.14159265358979323846;

// Gauss-Legendre nodes/weights on [-1, 1] (Newton on P_n).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1, p1 = z;
      double dp = n * (z * p1 - p0) / (z * z - 1);
      double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    double p0 = 1, p1 = z;
    for (int k = 2; k <= n; ++k) {
      double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    double dp = n * (z * p1 - p0) / (z * z - 1);
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

void legendre_all(int n, double z, double* p) {
  p[0] = 1;
  if (n >= 1) p[1] = z;
  for (int k = 2; k <= n; ++k) p[k] = ((2 * k - 1) * z * p[k - 1] - (k - 1) * p[k - 2]) / k;
}

}  // namespace

TwoSphereResult solve_two_spheres(const TwoSphereInput& in) {
  const int N = in.N;
  const int Q = in.Q > 0 ? in.Q : std::max(200, 3 * N);
  std::vector<double> mu, wq;
  gauss_legendre(Q, mu, wq);
  const double a[2] = {in.a1, in.a2}, kap[2] = {in.k1, in.k2}, zc[2] = {0.0, in.t}, q[2] = {in.q1, in.q2};
  const double k0 = in.k0;
  // Kq[i](qp, n): potential * eps0 at quadrature point qp of sphere i due to unit s_o^n of the
  // other sphere o: a_o^(n+2)/(2n+1) P_n(cos th_o) / r_o^(n+1).
  std::vector<Eigen::MatrixXd> K(2, Eigen::MatrixXd(Q, N + 1));
  std::vector<Eigen::MatrixXd> Ez(2, Eigen::MatrixXd(Q, N + 1));  // eps0 * E_z of the other sphere
  std::vector<double> P(N + 2);
  for (int i = 0; i < 2; ++i) {
    int o = 1 - i;
    for (int qp = 0; qp < Q; ++qp) {
      double st = std::sqrt(std::max(0.0, 1 - mu[qp] * mu[qp]));
      double x = a[i] * st, z = zc[i] + a[i] * mu[qp] - zc[o];
      double r = std::hypot(x, z), c = z / r;
      legendre_all(N + 1, c, P.data());
      double ar = a[o] / r;  // (a_o/r)^(n+1) * a_o
      double pw = ar;
      for (int n = 0; n <= N; ++n) {
        K[i](qp, n) = a[o] * pw * P[n] / (2 * n + 1);
        // d/dz [P_n / r^(n+1)] = -(n+1) P_{n+1} / r^(n+2)  ->  E_z = +(n+1) P_{n+1}/r^(n+2) * coef
        Ez[i](qp, n) = a[o] * pw * (n + 1) * P[n + 1] / (r * (2 * n + 1));
        pw *= ar;
      }
    }
  }
  // System in unknowns s = [s_1^0..s_1^N, s_2^0..s_2^N].
  const int M = 2 * (N + 1);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(M, M);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(M);
  std::vector<Eigen::MatrixXd> Proj(2, Eigen::MatrixXd(N + 1, N + 1));  // c_i^l per unit s_o^n
  for (int i = 0; i < 2; ++i) {
    Eigen::MatrixXd PL(N + 1, Q);
    for (int qp = 0; qp < Q; ++qp) {
      legendre_all(N, mu[qp], P.data());
      for (int l = 0; l <= N; ++l) PL(l, qp) = (2 * l + 1) / 2.0 * wq[qp] * P[l];
    }
    Proj[i] = PL * K[i];
    int o = 1 - i;
    for (int l = 0; l <= N; ++l) {
      int row = i * (N + 1) + l;
      A(row, row) = (k0 * (l + 1) + kap[i] * l) / (2 * l + 1);
      for (int n = 0; n <= N; ++n) A(row, o * (N + 1) + n) -= (k0 - kap[i]) * (l / a[i]) * Proj[i](l, n);
    }
    b(i * (N + 1)) = q[i] / (4 * kPi * a[i] * a[i]);
  }
  Eigen::VectorXd s = A.partialPivLu().solve(b);
  TwoSphereResult res;
  // forces: F_z,i = kappa0 2 pi a_i^2 \int sigma_i(mu) E_z,other(mu) dmu
  for (int i = 0; i < 2; ++i) {
    int o = 1 - i;
    Eigen::VectorXd so = s.segment(o * (N + 1), N + 1), si = s.segment(i * (N + 1), N + 1);
    Eigen::VectorXd ez = Ez[i] * so / kEps0;
    double f = 0;
    for (int qp = 0; qp < Q; ++qp) {
      legendre_all(N, mu[qp], P.data());
      double sig = 0;
      for (int n = 0; n <= N; ++n) sig += si(n) * P[n];
      f += wq[qp] * sig * ez(qp);
    }
    f *= k0 * 2 * kPi * a[i] * a[i];
    (i == 0 ? res.fz1 : res.fz2) = f;
    // energy: mean potential on sphere i = own s_i^0 a_i / eps0 + other's c_i^0 / eps0
    double own = si(0) * a[i] / kEps0;
    double other = (Proj[i].row(0) * so)(0) / kEps0;
    res.energy += 0.5 * q[i] * (own + other);
  }
  return res;
}

double point_charge_sphere_energy(double q, double d, double r0, double kt) {
  double x = d / r0, sum = 0;
  for (int n = 0; n < 100000; ++n) {
    double term = (1 - kt) * n * std::pow(1 + x, -2.0 * (n + 1)) / ((1 + kt) * n + 1);
    sum += term;
    if (n > 10 && std::abs(term) < 1e-18 * std::abs(sum)) break;
  }
  return q * q / (16 * kPi * kEps0 * d) * 2 * x * sum;
}

}  // namespace agglo::es::testref
