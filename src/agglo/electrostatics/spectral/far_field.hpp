#pragma once
// Fast far field of the spectral solver's matrix-vector product (issue 25 item 1;
// electrostatics.far_field = "fmm"; Lindgren et al. 2018, J. Comput. Phys. 371, 712, sec. 4).
//
// An adaptive octree over the sphere centres (fmm/octree.hpp) whose cells carry the extent
//   r_C = max_{i in C} (|x_i - c_C| + a_i)   (sphere radii included, not only centres).
// Cell pairs are classified by a symmetric dual-tree traversal with the acceptance criterion
//   r_A + r_B < theta |c_A - c_B|:
// accepted pairs interact through expansions of order p: each sphere's exterior multipole (degrees
// <= min(p, L), complex_basis.hpp) is shifted to its leaf (M2M), leaves to parents (M2M), accepted
// cells exchange M2L, locals go down (L2L) and are shifted to every sphere centre and added to its
// local coefficients (degrees <= min(p, L)); operators of fmm/operators.hpp. All other sphere pairs are
// "near": the caller re-expands them directly (spectral_solver.cpp, the pair degree their gap needs).
// Error: the M2L truncation bound of fmm/operators.hpp, |dphi| <= Q/(D - rho) (rho/D)^(p+1) with
// rho/D < theta, decays like theta^p; measured at theta = 0.5 on random clusters (N = 50, 200, radius
// ratio 1 and 3, gaps from 0.01 r, the multipoles of the solution; tests/electrostatics/
// test_spectral_far_field.cpp), the relative 2-norm error of the product against the dense twin is
// below kFarFieldErrorPrefactor kFarFieldErrorRatio^p (p = 2..8: 7e-3, 7e-4, 8e-5, 1e-5 at N = 200),
// and p is the smallest order with that model <= tolerance.
// The geometry (tree, lists) is fixed at construction; add() runs once per matrix-vector product.
#include <array>
#include <memory>
#include <vector>

#include "agglo/electrostatics/fmm/octree.hpp"
#include "agglo/electrostatics/fmm/solid_harmonics.hpp"
#include "agglo/electrostatics/solver.hpp"
#include "agglo/electrostatics/spectral/complex_basis.hpp"

namespace agglo::es::sh {

// Acceptance parameter, leaf size and prefactor of the error model (see the header comment).
inline constexpr double kFarFieldTheta = 0.5;
inline constexpr int kFarFieldLeafSize = 8;
inline constexpr double kFarFieldErrorPrefactor = 0.1;
inline constexpr double kFarFieldErrorRatio = 0.35;
// Passes over at least this many cells run in parallel (see spectral_solver.cpp on spinning threads).
inline constexpr std::size_t kParallelCells = 64;

struct FarFieldOptions {
  double theta = kFarFieldTheta;
  int leaf_size = kFarFieldLeafSize;
  double tolerance = 1e-6;  // relative accuracy of the far-field part of the product
  int order = 0;            // expansion order p (0 = from tolerance)
  // Near pairs of degree >= 20 (spectral_solver.cpp) rotate through their own stored blocks, as in the
  // dense product (the twin of the shared quarter turns, pivot_rotation.hpp).
  bool stored_rotations = false;
};

// Smallest p in [2, 30] with kFarFieldErrorPrefactor kFarFieldErrorRatio^p <= tol (theta = 0.5).
int far_field_order(double tol);

class SphereFarField {
 public:
  // Spheres of p (centres, radii), solver degree L (coefficients per sphere: ncoef(L)).
  SphereFarField(const Problem& p, int L, const FarFieldOptions& o);
  // Sphere pairs (i < k, sorted) the far field leaves out: the caller adds them directly.
  const std::vector<std::array<int, 2>>& near_pairs() const { return near_; }
  // alpha += the far-field part of M beta (scaled coefficients of spectral_solver.cpp).
  void add(const double* beta, double* alpha) const;
  int order() const { return p_; }
  std::size_t m2l_count() const { return n_m2l_; }
  double cells() const { return static_cast<double>(tree_.cells.size()); }
  // Whether the M2L pass runs in parallel (kParallelCells cells or more; the result does not depend on
  // it nor on the thread count: every cell and sphere sums its own terms in a fixed order).
  bool parallel() const { return tree_.cells.size() >= kParallelCells; }

 private:
  void classify(double theta);
  void upward(const double* beta) const;
  void interact() const;
  void downward(double* alpha) const;
  fmm::Octree tree_;                   // over centres / ell; Cell::radius = extent r_C / ell
  std::vector<double> rho_;            // sphere radii / ell, in tree order
  std::vector<std::vector<int>> m2l_;  // per target cell: source cells
  std::vector<std::array<int, 2>> near_;
  std::size_t n_m2l_ = 0;
  int L_ = 0, p_ = 0;
  ComplexBasis basis_;
  mutable std::vector<fmm::cplx> M_, Lc_;    // per cell, tri_size(p)
  mutable std::vector<double> Mre_, Mim_;    // per cell, (p + 1)^2
};

}  // namespace agglo::es::sh
