#pragma once
// Laplace fast multipole method (own implementation; adaptive octree + dual-tree traversal in the
// style of Dehnen 2002 / Greengard-Rokhlin expansions in complex solid harmonics, see
// solid_harmonics.hpp). Computes, for sources s_j with charges q_j and targets t_i,
//   phi_i = sum_j q_j / |t_i - s_j|,     E_i = -grad phi = sum_j q_j (t_i - s_j) / |t_i - s_j|^3
// skipping zero-distance pairs (self interaction when targets == sources).
// Operators: P2M, M2M, M2L (truncated at n + j <= p), L2L, L2P (potential and gradient from the
// degree-0/1 coefficients of the local expansion shifted to the target), P2P near field; one
// function each in operators.hpp (with their error bounds), evaluate() runs the passes.
// Accuracy is set by the expansion order p and the opening angle theta (MAC
// r_T + r_S < theta |c_T - c_S|); measured errors vs p are in docs/bem_fmm.md.
// The tree and interaction lists are built once in the constructor and reused by every
// evaluate() call (the BEM calls evaluate once per GMRES iteration on a fixed geometry). When the
// calling thread's cancel token is set (core/cancel.hpp), a pass skips its remaining cells and
// evaluate() throws InterruptedError after it.
#include <span>
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/electrostatics/fmm/octree.hpp"

namespace agglo::es::fmm {

struct FmmOptions {
  int order = 10;        // expansion order p (>= 1)
  int leaf_size = 64;    // max points per leaf
  double theta = 0.4;    // opening angle of the multipole acceptance criterion (0, 1)
};

// Measured error model (theta = 0.4, leaf 64): relative field error <= prefactor * ratio^p.
inline constexpr double kFmmErrorPrefactor = 2e-2;
inline constexpr double kFmmErrorRatio = 0.37;
// Smallest expansion order p whose modelled relative field error is below `tol`.
int order_for_tolerance(double tol);

class LaplaceFmm {
 public:
  // Targets are the sources themselves (self pairs skipped).
  LaplaceFmm(std::span<const Vec3> points, const FmmOptions& opt);
  // Separate target set.
  LaplaceFmm(std::span<const Vec3> sources, std::span<const Vec3> targets, const FmmOptions& opt);

  // Potential and/or field (either pointer may be null) at the targets, in input order.
  void evaluate(std::span<const double> charges, std::vector<double>* potential,
                std::vector<Vec3>* field) const;

  std::size_t num_sources() const { return src_.order.size(); }
  std::size_t num_targets() const { return tgt().order.size(); }
  const InteractionLists& lists() const { return lists_; }
  const FmmOptions& options() const { return opt_; }

 private:
  const Octree& tgt() const { return same_ ? src_ : tgt_; }
  FmmOptions opt_;
  bool same_ = true;
  Octree src_, tgt_;
  InteractionLists lists_;
};

}  // namespace agglo::es::fmm
