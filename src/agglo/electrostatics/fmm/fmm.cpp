#include "agglo/electrostatics/fmm/fmm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "agglo/core/cancel.hpp"
#include "agglo/electrostatics/fmm/operators.hpp"

namespace agglo::es::fmm {

namespace {

// The cancel token of the calling thread, read inside the OpenMP regions below (their threads have
// none of their own): a cancelled run skips the rest of a pass, and evaluate() throws after it.
bool cancelled(const CancelToken* token) { return token && token->cancelled(); }

void check_options(const FmmOptions& o) {
  if (o.order < 1 || o.order > 40) throw std::invalid_argument("fmm: order must be in [1, 40]");
  if (o.leaf_size < 1) throw std::invalid_argument("fmm: leaf_size must be >= 1");
  if (!(o.theta > 0.0 && o.theta < 1.0)) throw std::invalid_argument("fmm: theta must be in (0, 1)");
}

// Upward pass: P2M at the leaves, M2M into the parents, deepest level first.
std::vector<cplx> upward_pass(const Octree& S, const std::vector<double>& q, int p) {
  const int ts = tri_size(p);
  std::vector<cplx> M(S.cells.size() * ts, cplx(0.0, 0.0));
  const CancelToken* cancel = current_cancel_token();  // OpenMP threads have none of their own
  for (int lev = S.levels() - 1; lev >= 0; --lev) {
#pragma omp parallel
    {
      OperatorScratch scratch(p);
#pragma omp for schedule(dynamic, 4)
      for (int c = S.level_begin[lev]; c < S.level_begin[lev + 1]; ++c) {
        if (cancelled(cancel)) continue;  // skip the rest; evaluate() throws after the pass
        const Cell& cell = S.cells[c];
        cplx* Mc = &M[c * ts];
        if (cell.leaf()) {
          p2m(S.sorted, cell.begin, cell.end, q.data(), cell.center, p, Mc, scratch);
        } else {
          for (int ch = cell.child; ch < cell.child + cell.nchild; ++ch)
            m2m(&M[ch * ts], S.cells[ch].center - cell.center, p, Mc, scratch);
        }
      }
    }
  }
  return M;
}

// M2L of every source cell in a target cell's list into that cell's local expansion.
std::vector<cplx> m2l_pass(const Octree& T, const Octree& S, const InteractionLists& lists,
                           const std::vector<cplx>& M, int p) {
  const int ts = tri_size(p);
  const int fs = (p + 1) * (p + 1);
  const std::size_t nsc = S.cells.size();
  // Full (all m) split real/imag multipoles for the M2L inner loop.
  std::vector<double> Mre(nsc * fs), Mim(nsc * fs);
#pragma omp parallel for schedule(static)
  for (std::size_t c = 0; c < nsc; ++c) split_multipole(&M[c * ts], p, &Mre[c * fs], &Mim[c * fs]);

  const std::size_t ntc = T.cells.size();
  std::vector<cplx> L(ntc * ts, cplx(0.0, 0.0));
  const CancelToken* cancel = current_cancel_token();
#pragma omp parallel
  {
    OperatorScratch scratch(p);
#pragma omp for schedule(dynamic, 2)
    for (std::size_t c = 0; c < ntc; ++c)
      for (int b : lists.m2l[c])
        if (!cancelled(cancel))
        m2l(&Mre[b * fs], &Mim[b * fs], T.cells[c].center - S.cells[b].center, p, &L[c * ts], scratch);
  }
  return L;
}

// Downward pass: L2L from each parent into its children, top level first.
void downward_pass(const Octree& T, int p, std::vector<cplx>& L) {
  const int ts = tri_size(p);
  for (int lev = 1; lev < T.levels(); ++lev) {
#pragma omp parallel
    {
      OperatorScratch scratch(p);
#pragma omp for schedule(dynamic, 4)
      for (int c = T.level_begin[lev]; c < T.level_begin[lev + 1]; ++c) {
        const Cell& cell = T.cells[c];
        l2l(&L[cell.parent * ts], cell.center - T.cells[cell.parent].center, p, &L[c * ts], scratch);
      }
    }
  }
}

// Potential and field at the targets in sorted order.
struct LeafSums {
  explicit LeafSums(std::size_t n) : phi(n, 0.0), ex(n, 0.0), ey(n, 0.0), ez(n, 0.0) {}
  std::vector<double> phi, ex, ey, ez;
};

// At every target leaf: L2P for its points, then P2P from the source leaves of its near list.
void leaf_pass(const Octree& T, const Octree& S, const InteractionLists& lists, const std::vector<cplx>& L,
               const std::vector<double>& q, int p, bool want_field, LeafSums& out) {
  const int ts = tri_size(p);
  const Points& tp = T.sorted;
  const CancelToken* cancel = current_cancel_token();
#pragma omp parallel
  {
    OperatorScratch scratch(p);
#pragma omp for schedule(dynamic, 2)
    for (std::size_t c = 0; c < T.cells.size(); ++c) {
      const Cell& cell = T.cells[c];
      if (!cell.leaf() || cancelled(cancel)) continue;
      for (int i = cell.begin; i < cell.end; ++i) {
        Vec3 e;
        out.phi[i] += l2p(&L[c * ts], Vec3{tp.x[i], tp.y[i], tp.z[i]} - cell.center, p, want_field ? &e : nullptr,
                          scratch);
        if (want_field) {
          out.ex[i] += e.x;
          out.ey[i] += e.y;
          out.ez[i] += e.z;
        }
      }
      for (int b : lists.p2p[c]) {
        const Cell& sc = S.cells[b];
        p2p(tp, cell.begin, cell.end, S.sorted, sc.begin, sc.end, q.data(), out.phi.data(),
            want_field ? out.ex.data() : nullptr, out.ey.data(), out.ez.data());
      }
    }
  }
}

}  // namespace

int order_for_tolerance(double tol) {
  // Calibrated with theta = 0.4, leaf 64 (docs/bem_fmm.md): the relative 2-norm field error on
  // points on touching sphere surfaces (the worse of surface and volume sets) is below
  // kFmmErrorPrefactor * kFmmErrorRatio^p.
  tol = std::clamp(tol, 1e-15, 0.1);
  const int p = static_cast<int>(std::ceil(std::log(tol / kFmmErrorPrefactor) / std::log(kFmmErrorRatio)));
  return std::clamp(p, 2, 30);
}

LaplaceFmm::LaplaceFmm(std::span<const Vec3> points, const FmmOptions& opt)
    : opt_(opt), same_(true), src_(points, opt.leaf_size) {
  check_options(opt);
  lists_ = build_interaction_lists(src_, src_, opt.theta);
}

LaplaceFmm::LaplaceFmm(std::span<const Vec3> sources, std::span<const Vec3> targets, const FmmOptions& opt)
    : opt_(opt), same_(false), src_(sources, opt.leaf_size), tgt_(targets, opt.leaf_size) {
  check_options(opt);
  lists_ = build_interaction_lists(tgt_, src_, opt.theta);
}

void LaplaceFmm::evaluate(std::span<const double> charges, std::vector<double>* potential,
                          std::vector<Vec3>* field) const {
  const Octree& S = src_;
  const Octree& T = tgt();
  const int p = opt_.order;
  const std::size_t ns = S.order.size(), nt = T.order.size();
  if (charges.size() != ns) throw std::invalid_argument("fmm: charges size differs from sources");
  if (ns == 0 || nt == 0) {
    if (potential) potential->assign(nt, 0.0);
    if (field) field->assign(nt, Vec3{});
    return;
  }
  std::vector<double> q(ns);
  for (std::size_t k = 0; k < ns; ++k) q[k] = charges[S.order[k]];

  // A cancelled run skips the rest of a pass and stops after it (core/cancel.hpp).
  const std::vector<cplx> M = upward_pass(S, q, p);
  poll_cancel();
  std::vector<cplx> L = m2l_pass(T, S, lists_, M, p);
  poll_cancel();
  downward_pass(T, p, L);
  poll_cancel();
  LeafSums out(nt);
  leaf_pass(T, S, lists_, L, q, p, field != nullptr, out);
  poll_cancel();

  // ---- back to input order ----
  if (potential) {
    potential->assign(nt, 0.0);
    for (std::size_t k = 0; k < nt; ++k) (*potential)[T.order[k]] = out.phi[k];
  }
  if (field) {
    field->assign(nt, Vec3{});
    for (std::size_t k = 0; k < nt; ++k) (*field)[T.order[k]] = {out.ex[k], out.ey[k], out.ez[k]};
  }
}

}  // namespace agglo::es::fmm
