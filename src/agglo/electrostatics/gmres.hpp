#pragma once
// Restarted GMRES(m) (Saad & Schultz 1986) for a matrix-free operator: `A(x, y)` computes y = A x.
// Each cycle starts from the explicit residual r = b - A x, builds an m-step Krylov basis by Arnoldi
// with modified Gram-Schmidt, reduces the Hessenberg matrix with Givens rotations, and adds the
// least-squares correction to x. Inner product: <u, v> = sum_i w_i u_i v_i with the weights w (area
// weights for the BEM, so that the norm approximates the L2 norm on the surface); empty weights give
// the Euclidean product, summed in fixed blocks of 4096 numbers (8 interleaved partial sums each, the
// block sums in block order, blocks in parallel for long vectors: the same bits at any thread count);
// the weighted product is one sequential sum. Stopping rule: ||b - A x|| <= tol ||b|| in that norm. A
// cycle ends when the Givens residual estimate meets it; with `recheck_true_residual` the residual is
// then recomputed explicitly (one extra operator application) and GMRES restarts if that is still above
// tol.
// After every operator application the calling thread's cancel token is polled (core/cancel.hpp):
// InterruptedError when it is set.
#include <functional>
#include <span>
#include <vector>

#include "agglo/electrostatics/large_buffer.hpp"

namespace agglo::es {

// y = A x; x and y never alias and y is fully overwritten.
using LinearOperator = std::function<void(std::span<const double> x, std::span<double> y)>;

struct GmresOptions {
  double tolerance = 1e-8;  // relative residual target
  int max_iterations = 1000;  // Arnoldi steps (operator applications inside the Krylov cycles)
  int restart = 50;  // Krylov dimension m per cycle (clamped to [1, max_iterations])
  // true: when a cycle's estimate says converged (or the budget is spent), recompute b - A x
  // explicitly, report that, and restart if it is still above tol. false: trust the Givens
  // estimate and return without that operator application.
  bool recheck_true_residual = true;
};

struct GmresResult {
  int iterations = 0;      // operator applications inside Arnoldi
  int matvecs = 0;         // all operator applications (including explicit residuals)
  double residual = 0.0;   // final relative residual (true residual if it was recomputed, else estimate)
  bool converged = false;
};

// Reusable storage (Krylov basis, Hessenberg matrix, rotations): repeated solves of the same size
// and restart length do not allocate.
struct GmresWorkspace {
  LargeVector V;  // (restart + 1) basis vectors of length n, contiguous
  std::vector<double> H, cs, sn, g, y;
};

// x holds the initial guess on entry and the solution on exit; x and weights (if not empty) have the
// size of b. Without a workspace, a temporary one is used.
GmresResult gmres(const LinearOperator& A, std::span<const double> b, std::span<double> x,
                  std::span<const double> weights, const GmresOptions& opt, GmresWorkspace* ws = nullptr);

}  // namespace agglo::es
