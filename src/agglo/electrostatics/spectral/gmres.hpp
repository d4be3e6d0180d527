#pragma once
// Restarted GMRES(m) (Saad & Schultz 1986) with modified Gram-Schmidt and Givens rotations, for
// the small dense-ish systems of the spectral solver. Matrix-free: `apply(x, y)` computes y = A x.
// Euclidean inner product; stops when ||b - A x|| <= tol ||b||.
#include <cmath>
#include <functional>
#include <vector>

namespace agglo::es {

struct GmresResult {
  int iterations = 0;       // matrix-vector products (excluding the initial residual)
  double residual = 0.0;    // final relative residual ||b - A x|| / ||b||
  bool converged = false;
};

// Reusable storage (Krylov basis etc.), so that repeated solves do not allocate.
struct GmresWorkspace {
  std::vector<std::vector<double>> V;
  std::vector<double> H, cs, sn, g, w, y;
};

GmresResult gmres(const std::function<void(const double*, double*)>& apply, const std::vector<double>& b,
                  std::vector<double>& x, double tol, int max_iterations, int restart, GmresWorkspace& ws);

}  // namespace agglo::es
