#pragma once
// The discretised BEM equation of docs/bem_fmm.md (docs/model.md §B.2 item 2), matrix free:
//   (A x)_i = kbar_i x_i + dk_i (n_i . E[x]_i + self_i x_i),
//   E[x]_i = sum_{j != i} x_j a_j (r_i - r_j) / (4 pi |r_i - r_j|^3)      (1/eps0 cancels),
// kbar = (kappa_p + kappa_0)/2, dk = kappa_0 - kappa_p, self_i = sqrt(a_i) / (4 R sqrt(pi)) (BSL eq.
// 55), and the projector P onto zero net charge per body (area-weighted mean removal). The sum
// E[x] is evaluated by the FMM (matvec "fmm") or by the direct pair loop ("direct").
#include <optional>
#include <span>
#include <vector>

#include "agglo/electrostatics/fmm/direct.hpp"
#include "agglo/electrostatics/fmm/fmm.hpp"
#include "agglo/electrostatics/solver.hpp"

namespace agglo::es::bem {

// All patches of all spheres, body-major (patch k of body b is entry b * np + k).
struct PatchSet {
  std::size_t nb = 0, np = 0, n = 0;  // bodies, patches per body, total
  std::vector<Vec3> pos, nrm;         // patch centre [m], outward unit normal
  std::vector<double> area;           // [m^2]
  std::vector<double> kbar, dk, self;  // coefficients of A (see above)
  std::vector<double> sigma_f;        // free charge density [C/m^2], uniform per body
  std::vector<int> body;
};

// Patches of every sphere from the unit-sphere directions `unit` (equal areas 4 pi R^2 / np).
PatchSet make_patch_set(const Problem& prob, const std::vector<Vec3>& unit);

class BemOperator {
 public:
  BemOperator(const PatchSet& ps, const SolverOptions& opt);
  // out = A x (uses internal buffers: not thread safe).
  void apply(std::span<const double> x, std::span<double> out);
  // v <- P v.
  void project(std::span<double> v) const;
  // Potential sum_j q_j / |r_i - r_j| and field sum_j q_j (r_i - r_j) / |r_i - r_j|^3 at the patches.
  void fields(std::span<const double> q, std::vector<double>* potential, std::vector<Vec3>* field) const;
  int fmm_order() const { return order_; }  // 0 for the direct matvec
  bool uses_fmm() const { return fmm_.has_value(); }
  std::size_t fmm_m2l_pairs() const { return fmm_ ? fmm_->lists().n_m2l : 0; }

 private:
  const PatchSet& ps_;
  std::optional<fmm::LaplaceFmm> fmm_;
  int order_ = 0;
  fmm::Points pts_, nrms_;
  std::vector<double> q_, y_;
  std::vector<Vec3> field_;
};

}  // namespace agglo::es::bem
