#include "agglo/electrostatics/bem/gmres.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace agglo::es::bem {

namespace {
double wdot(std::span<const double> w, std::span<const double> a, std::span<const double> b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += w[i] * a[i] * b[i];
  return s;
}
}  // namespace

GmresResult gmres(const LinearOp& A, std::span<const double> b, std::span<double> x,
                  std::span<const double> w, double tol, int max_iterations, int restart) {
  const std::size_t n = b.size();
  GmresResult res;
  const double bnorm = std::sqrt(wdot(w, b, b));
  if (bnorm == 0.0) {
    std::fill(x.begin(), x.end(), 0.0);
    res.converged = true;
    return res;
  }
  restart = std::max(1, restart);
  std::vector<std::vector<double>> V(restart + 1, std::vector<double>(n));
  std::vector<double> H((restart + 1) * restart), cs(restart), sn(restart), g(restart + 1), r(n), y;
  auto h = [&](int i, int k) -> double& { return H[i * restart + k]; };
  while (true) {
    A(x, r);
    ++res.matvecs;
    for (std::size_t i = 0; i < n; ++i) r[i] = b[i] - r[i];
    const double beta = std::sqrt(wdot(w, r, r));
    res.residual = beta / bnorm;
    if (!std::isfinite(res.residual)) return res;
    if (res.residual <= tol) {
      res.converged = true;
      return res;
    }
    if (res.iterations >= max_iterations) return res;
    for (std::size_t i = 0; i < n; ++i) V[0][i] = r[i] / beta;
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = beta;
    int k = 0;
    for (; k < restart && res.iterations < max_iterations; ++k) {
      std::vector<double>& v = V[k + 1];
      A(V[k], v);
      ++res.matvecs;
      ++res.iterations;
      for (int i = 0; i <= k; ++i) {
        h(i, k) = wdot(w, v, V[i]);
        for (std::size_t j = 0; j < n; ++j) v[j] -= h(i, k) * V[i][j];
      }
      const double hn = std::sqrt(wdot(w, v, v));
      h(k + 1, k) = hn;
      if (hn > 0.0)
        for (std::size_t j = 0; j < n; ++j) v[j] /= hn;
      for (int i = 0; i < k; ++i) {
        const double t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
        h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
        h(i, k) = t;
      }
      const double den = std::hypot(h(k, k), h(k + 1, k));
      cs[k] = den > 0.0 ? h(k, k) / den : 1.0;
      sn[k] = den > 0.0 ? h(k + 1, k) / den : 0.0;
      h(k, k) = den;
      h(k + 1, k) = 0.0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      if (std::abs(g[k + 1]) <= tol * bnorm || hn == 0.0) {
        ++k;
        break;
      }
    }
    // Back substitution for the k x k upper triangular system, then x += V y.
    y.assign(k, 0.0);
    for (int i = k - 1; i >= 0; --i) {
      double s = g[i];
      for (int j = i + 1; j < k; ++j) s -= h(i, j) * y[j];
      y[i] = h(i, i) != 0.0 ? s / h(i, i) : 0.0;
    }
    for (int i = 0; i < k; ++i)
      for (std::size_t j = 0; j < n; ++j) x[j] += y[i] * V[i][j];
  }
}

}  // namespace agglo::es::bem
