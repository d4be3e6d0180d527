#include "agglo/electrostatics/gmres.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "agglo/core/cancel.hpp"

namespace agglo::es {

namespace {

// Element-wise updates of vectors at least this long run in parallel (OpenMP; each number is computed
// alone, so the bits do not depend on the thread count). The inner products stay sequential sums.
constexpr std::size_t kGmresParallelLength = std::size_t(1) << 18;

// Euclidean inner products (the spectral solver's) are summed in blocks of kDotBlock numbers, each block
// in kDotLanes interleaved partial sums added pairwise, and the block sums in block order: the grouping
// depends on the length only, never on the thread count, so the bits are the same at any thread count.
// The blocks run in parallel from kGmresParallelLength numbers on, and the lanes let the compiler
// vectorise (one running sum is a chain of dependent additions: 2.3e6 of them for each of the ~170
// inner products of a 1000-sphere spectral solve at 17 iterations, issue 25). The weighted products
// (the BEM's) stay one sequential sum each, so the BEM's results keep their bits.
constexpr std::size_t kDotBlock = 4096;
constexpr std::size_t kDotLanes = 8;

// Lanes of one block, added pairwise.
double sum_dot_lanes(const double (&acc)[kDotLanes]) {
  return ((acc[0] + acc[1]) + (acc[2] + acc[3])) + ((acc[4] + acc[5]) + (acc[6] + acc[7]));
}

// sum_j a_j b_j over one block of `len` numbers (lanes j mod kDotLanes; a tail shorter than a lane
// group goes to lane 0).
double block_dot(const double* a, const double* b, std::size_t len) {
  double acc[kDotLanes] = {};
  std::size_t j = 0;
  for (; j + kDotLanes <= len; j += kDotLanes)
    for (std::size_t l = 0; l < kDotLanes; ++l) acc[l] += a[j + l] * b[j + l];
  for (; j < len; ++j) acc[0] += a[j] * b[j];
  return sum_dot_lanes(acc);
}

// v -= d u over one block, and the sum of the updated v_j times w_j (block_dot's order): the modified
// Gram-Schmidt update and the next inner product in one pass over v (w may be v itself).
double block_update_dot(double* v, double d, const double* u, const double* w, std::size_t len) {
  double acc[kDotLanes] = {};
  std::size_t j = 0;
  for (; j + kDotLanes <= len; j += kDotLanes)
    for (std::size_t l = 0; l < kDotLanes; ++l) {
      v[j + l] -= d * u[j + l];
      acc[l] += v[j + l] * w[j + l];
    }
  for (; j < len; ++j) {
    v[j] -= d * u[j];
    acc[0] += v[j] * w[j];
  }
  return sum_dot_lanes(acc);
}

// Blocks of kDotBlock numbers over n: f(j0, len) gives each block's sum; the sums are added in block order.
template <class BlockSum>
double sum_blocks(std::size_t n, BlockSum&& f) {
  const std::size_t nb = (n + kDotBlock - 1) / kDotBlock;
  std::vector<double> part(nb);
#pragma omp parallel for schedule(static) if (n >= kGmresParallelLength)
  for (std::size_t b = 0; b < nb; ++b) part[b] = f(b * kDotBlock, std::min(kDotBlock, n - b * kDotBlock));
  double s = 0.0;
  for (double x : part) s += x;
  return s;
}

// sum_i a_i b_i in blocks and lanes (above).
double euclidean_dot(std::span<const double> a, std::span<const double> b) {
  return sum_blocks(a.size(), [&](std::size_t j0, std::size_t len) { return block_dot(&a[j0], &b[j0], len); });
}

// v -= d u, then <v, w> (w may be v), as euclidean_dot would sum it.
double update_then_dot(std::span<double> v, double d, std::span<const double> u, std::span<const double> w) {
  return sum_blocks(v.size(),
                    [&](std::size_t j0, std::size_t len) { return block_update_dot(&v[j0], d, &u[j0], &w[j0], len); });
}

// <a, b> = sum_i w_i a_i b_i, evaluated as (w_i a_i) b_i, one sequential sum; empty w: euclidean_dot.
// Both give the same bit pattern on every run and at any thread count.
double dot(std::span<const double> w, std::span<const double> a, std::span<const double> b) {
  if (w.empty()) return euclidean_dot(a, b);
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += w[i] * a[i] * b[i];
  return s;
}

// The workspace seen as a Krylov basis V(0..m) of length-n vectors and an (m+1) x m Hessenberg matrix.
// The basis is reserved whole but its vectors are sized (and their pages touched) only when the
// iteration reaches them (use(k)): a solve of 10 iterations does not zero a basis of m + 1 vectors
// (1.1 GB for 1000 spheres at L = 47). Every vector is written before it is read, so sizing one does not
// zero it, and its blocks lie on huge pages (LargeBufferAllocator, large_buffer.hpp).
struct Krylov {
  Krylov(GmresWorkspace& ws, std::size_t n_, int m_) : w(ws), n(n_), m(m_) {
    const std::size_t full = (static_cast<std::size_t>(m) + 1) * n;
    if (w.V.capacity() < full) {
      w.V.clear();
      w.V.reserve(full);
    }
    use(0);
    w.H.resize(static_cast<std::size_t>(m + 1) * m);
    w.cs.resize(m);
    w.sn.resize(m);
    w.g.resize(m + 1);
  }
  std::span<double> V(int k) const { return std::span<double>(w.V.data() + static_cast<std::size_t>(k) * n, n); }
  // Basis vectors 0..k sized (within the reserved capacity: V's data does not move).
  void use(int k) const {
    if (w.V.size() < (static_cast<std::size_t>(k) + 1) * n) w.V.resize((static_cast<std::size_t>(k) + 1) * n);
  }
  double& h(int i, int k) const { return w.H[static_cast<std::size_t>(i) * m + k]; }
  GmresWorkspace& w;
  std::size_t n;
  int m;
};

// Modified Gram-Schmidt of v against V(0..k), the coefficients into column k of H; returns <v, v> after.
// Euclidean: each update of v and the next inner product share one pass (update_then_dot).
double orthogonalise_euclidean(const Krylov& K, int k, std::span<double> v) {
  double d = euclidean_dot(v, K.V(0));
  for (int i = 0; i <= k; ++i) {
    K.h(i, k) = d;
    d = update_then_dot(v, d, K.V(i), i < k ? std::span<const double>(K.V(i + 1)) : std::span<const double>(v));
  }
  return d;
}

// Weighted (sequential inner products, as the BEM always had).
double orthogonalise_weighted(std::span<const double> weights, const Krylov& K, int k, std::span<double> v) {
  for (int i = 0; i <= k; ++i) {
    const std::span<const double> vi = K.V(i);
    const double d = dot(weights, v, vi);
    K.h(i, k) = d;
#pragma omp parallel for schedule(static) if (K.n >= kGmresParallelLength)
    for (std::size_t j = 0; j < K.n; ++j) v[j] -= d * vi[j];
  }
  return dot(weights, v, v);
}

// Arnoldi step k: V(k+1) = A V(k) orthogonalised against V(0..k) (modified Gram-Schmidt) and
// normalised; column k of H is reduced by the earlier Givens rotations and a new one that zeroes
// h(k+1, k), applied to g as well (|g[k+1]| is then the residual norm of the k+1-step least-squares
// solution). Returns the norm h(k+1, k) before the rotation (0: the Krylov space is invariant).
double arnoldi_step(const LinearOperator& A, std::span<const double> weights, const Krylov& K, int k) {
  auto& cs = K.w.cs;
  auto& sn = K.w.sn;
  auto& g = K.w.g;
  K.use(k + 1);
  const std::span<double> v = K.V(k + 1);
  A(K.V(k), v);
  const double vv = weights.empty() ? orthogonalise_euclidean(K, k, v) : orthogonalise_weighted(weights, K, k, v);
  const double hn = std::sqrt(vv);
  K.h(k + 1, k) = hn;
  if (hn > 0.0) {
#pragma omp parallel for schedule(static) if (K.n >= kGmresParallelLength)
    for (std::size_t j = 0; j < K.n; ++j) v[j] /= hn;
  }
  for (int i = 0; i < k; ++i) {
    const double t = cs[i] * K.h(i, k) + sn[i] * K.h(i + 1, k);
    K.h(i + 1, k) = -sn[i] * K.h(i, k) + cs[i] * K.h(i + 1, k);
    K.h(i, k) = t;
  }
  const double den = std::hypot(K.h(k, k), K.h(k + 1, k));
  cs[k] = den > 0.0 ? K.h(k, k) / den : 1.0;
  sn[k] = den > 0.0 ? K.h(k + 1, k) / den : 0.0;
  K.h(k, k) = den;
  K.h(k + 1, k) = 0.0;
  g[k + 1] = -sn[k] * g[k];
  g[k] = cs[k] * g[k];
  return hn;
}

// Back substitution for the k x k upper triangular system H y = g, then x += V y. A zero pivot
// (singular operator) leaves that component out; returns whether one was met.
bool update_solution(const Krylov& K, int k, std::span<double> x) {
  auto& y = K.w.y;
  y.assign(k, 0.0);
  bool zero_pivot = false;
  for (int i = k - 1; i >= 0; --i) {
    double s = K.w.g[i];
    for (int j = i + 1; j < k; ++j) s -= K.h(i, j) * y[j];
    zero_pivot = zero_pivot || K.h(i, i) == 0.0;
    y[i] = K.h(i, i) != 0.0 ? s / K.h(i, i) : 0.0;
  }
  // x_j += y_i V(i)_j for i = 0..k-1 in turn, every number alone: one pass over x (the same bits as k passes)
  const double* V = K.w.V.data();
  const std::size_t n = K.n;
#pragma omp parallel for schedule(static) if (n >= kGmresParallelLength)
  for (std::size_t j = 0; j < n; ++j) {
    double xj = x[j];
    for (int i = 0; i < k; ++i) xj += y[i] * V[std::size_t(i) * n + j];
    x[j] = xj;
  }
  return zero_pivot;
}

}  // namespace

GmresResult gmres(const LinearOperator& A, std::span<const double> b, std::span<double> x,
                  std::span<const double> weights, const GmresOptions& opt, GmresWorkspace* ws) {
  const std::size_t n = b.size();
  if (x.size() != n || (!weights.empty() && weights.size() != n))
    throw std::invalid_argument("gmres: x and weights must have the size of b");
  const bool weighted = !weights.empty();
  const double tol = opt.tolerance;
  const int max_iterations = opt.max_iterations;
  GmresResult res;
  const double bnorm = std::sqrt(dot(weights, b, b));
  if (bnorm == 0.0) {
    std::fill(x.begin(), x.end(), 0.0);
    res.converged = true;
    return res;
  }
  // Givens estimate |g| against tol ||b||. The two forms differ only in rounding; the Euclidean and
  // the weighted path each keep the form they always used, so that results stay bit-for-bit the same.
  auto estimate_small = [&](double gabs) { return weighted ? gabs <= tol * bnorm : gabs / bnorm <= tol; };

  const int m = std::max(1, std::min(opt.restart, max_iterations));
  GmresWorkspace local;
  const Krylov K(ws ? *ws : local, n, m);
  auto& g = K.w.g;
  while (true) {
    // Explicit residual r = b - A x; its normalisation is the first basis vector.
    const std::span<double> r = K.V(0);
    A(x, r);
    ++res.matvecs;
    poll_cancel();  // every operator application: a cancelled run stops here (core/cancel.hpp)
#pragma omp parallel for schedule(static) if (n >= kGmresParallelLength)
    for (std::size_t i = 0; i < n; ++i) r[i] = b[i] - r[i];
    const double beta = std::sqrt(dot(weights, r, r));
    res.residual = beta / bnorm;
    if (!std::isfinite(res.residual)) return res;
    if (res.residual <= tol) {
      res.converged = true;
      return res;
    }
    if (res.iterations >= max_iterations) return res;
#pragma omp parallel for schedule(static) if (n >= kGmresParallelLength)
    for (std::size_t i = 0; i < n; ++i) r[i] /= beta;
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = beta;

    int k = 0;
    bool estimate_converged = false;
    for (; k < m && res.iterations < max_iterations; ++k) {
      const double hn = arnoldi_step(A, weights, K, k);
      ++res.matvecs;
      poll_cancel();
      ++res.iterations;
      if (estimate_small(std::abs(g[k + 1])) || hn == 0.0) {
        estimate_converged = true;
        ++k;
        break;
      }
    }
    const bool zero_pivot = update_solution(K, k, x);

    const bool cycle_final = estimate_converged || res.iterations >= max_iterations;
    if (!opt.recheck_true_residual && !zero_pivot && cycle_final) {
      res.residual = std::abs(g[k]) / bnorm;
      res.converged = estimate_small(std::abs(g[k]));
      return res;
    }
  }
}

}  // namespace agglo::es
