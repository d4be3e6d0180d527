#pragma once
// Restarted GMRES (Saad & Schultz 1986) for a matrix-free operator, in the weighted inner
// product <u, v> = sum_i w_i u_i v_i (area weights for the BEM). Modified Gram-Schmidt Arnoldi,
// Givens rotations. Convergence: true relative residual ||b - A x||_w / ||b||_w <= tol,
// re-checked with an explicit residual at every restart and at the end.
#include <functional>
#include <span>

namespace agglo::es::bem {

using LinearOp = std::function<void(std::span<const double> in, std::span<double> out)>;

struct GmresResult {
  int iterations = 0;      // operator applications inside Arnoldi
  int matvecs = 0;         // all operator applications (including explicit residuals)
  double residual = 0.0;   // final true relative residual
  bool converged = false;
};

// x holds the initial guess on entry and the solution on exit.
GmresResult gmres(const LinearOp& A, std::span<const double> b, std::span<double> x,
                  std::span<const double> w, double tol, int max_iterations, int restart);

}  // namespace agglo::es::bem
