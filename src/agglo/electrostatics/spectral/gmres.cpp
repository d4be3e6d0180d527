#include "agglo/electrostatics/spectral/gmres.hpp"

#include <algorithm>

namespace agglo::es {

namespace {
double nrm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}
}  // namespace

GmresResult gmres(const std::function<void(const double*, double*)>& apply, const std::vector<double>& b,
                  std::vector<double>& x, double tol, int max_iterations, int restart, GmresWorkspace& ws) {
  const std::size_t n = b.size();
  GmresResult res;
  x.resize(n, 0.0);
  const double bn = nrm(b);
  if (bn == 0.0) {
    std::fill(x.begin(), x.end(), 0.0);
    res.converged = true;
    return res;
  }
  restart = std::max(1, std::min(restart, max_iterations));
  if (static_cast<int>(ws.V.size()) < restart + 1) ws.V.resize(restart + 1);
  for (int k = 0; k <= restart; ++k) ws.V[k].resize(n);
  ws.H.resize((restart + 1) * restart);
  ws.cs.resize(restart);
  ws.sn.resize(restart);
  ws.g.resize(restart + 1);
  ws.w.resize(n);
  auto& V = ws.V;
  auto& H = ws.H;
  auto& cs = ws.cs;
  auto& sn = ws.sn;
  auto& g = ws.g;
  auto& w = ws.w;
  auto h = [&](int i, int j) -> double& { return H[i * restart + j]; };
  while (true) {
    apply(x.data(), w.data());
    for (std::size_t i = 0; i < n; ++i) V[0][i] = b[i] - w[i];
    double beta = nrm(V[0]);
    res.residual = beta / bn;
    if (res.residual <= tol) {
      res.converged = true;
      return res;
    }
    if (res.iterations >= max_iterations) return res;
    for (std::size_t i = 0; i < n; ++i) V[0][i] /= beta;
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = beta;
    int k = 0;
    for (; k < restart && res.iterations < max_iterations; ++k) {
      apply(V[k].data(), w.data());
      ++res.iterations;
      for (int i = 0; i <= k; ++i) {
        double d = 0;
        for (std::size_t q = 0; q < n; ++q) d += w[q] * V[i][q];
        h(i, k) = d;
        for (std::size_t q = 0; q < n; ++q) w[q] -= d * V[i][q];
      }
      double hn = nrm(w);
      h(k + 1, k) = hn;
      if (hn > 0)
        for (std::size_t q = 0; q < n; ++q) V[k + 1][q] = w[q] / hn;
      for (int i = 0; i < k; ++i) {
        double t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
        h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
        h(i, k) = t;
      }
      double r = std::hypot(h(k, k), h(k + 1, k));
      cs[k] = r > 0 ? h(k, k) / r : 1.0;
      sn[k] = r > 0 ? h(k + 1, k) / r : 0.0;
      h(k, k) = r;
      h(k + 1, k) = 0.0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      if (std::abs(g[k + 1]) / bn <= tol || hn == 0.0) {
        ++k;
        break;
      }
    }
    // back substitution, update x
    auto& y = ws.y;
    y.assign(k, 0.0);
    for (int i = k - 1; i >= 0; --i) {
      double s = g[i];
      for (int j = i + 1; j < k; ++j) s -= h(i, j) * y[j];
      y[i] = s / h(i, i);
    }
    for (int j = 0; j < k; ++j)
      for (std::size_t q = 0; q < n; ++q) x[q] += y[j] * V[j][q];
  }
}

}  // namespace agglo::es
