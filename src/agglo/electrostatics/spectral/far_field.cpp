// Fast far field of the spectral product; see far_field.hpp.
#include "agglo/electrostatics/spectral/far_field.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/cancel.hpp"
#include "agglo/electrostatics/fmm/operators.hpp"
#include "agglo/electrostatics/spectral/harmonics.hpp"

namespace agglo::es::sh {

namespace {

// Centres in units of the largest radius (the expansions' powers stay near 1).
std::vector<Vec3> scaled_centres(const Problem& p, double ell) {
  std::vector<Vec3> x;
  x.reserve(p.spheres.size());
  for (const auto& s : p.spheres) x.push_back(s.center * (1.0 / ell));
  return x;
}

double largest_radius(const Problem& p) {
  double r = 0.0;
  for (const auto& s : p.spheres) r = std::max(r, s.radius);
  return r;
}

Vec3 sorted_point(const fmm::Octree& t, int k) { return {t.sorted.x[k], t.sorted.y[k], t.sorted.z[k]}; }

}  // namespace

int far_field_order(double tol) {
  const double p = std::log(std::max(tol, 1e-300) / kFarFieldErrorPrefactor) / std::log(kFarFieldErrorRatio);
  return std::clamp(static_cast<int>(std::ceil(p)), 2, 30);
}

SphereFarField::SphereFarField(const Problem& p, int L, const FarFieldOptions& o)
    : L_(L),
      p_(o.order > 0 ? o.order : far_field_order(o.tolerance)),
      basis_(p_) {
  const double ell = largest_radius(p);
  const auto x = scaled_centres(p, ell);
  tree_ = fmm::Octree(x, o.leaf_size);
  const int n = static_cast<int>(x.size());
  rho_.resize(n);
  for (int k = 0; k < n; ++k) rho_[k] = p.spheres[tree_.order[k]].radius / ell;
  for (auto& c : tree_.cells) {
    double r = 0.0;
    for (int k = c.begin; k < c.end; ++k) r = std::max(r, norm(sorted_point(tree_, k) - c.center) + rho_[k]);
    c.radius = r;
  }
  classify(o.theta);
  const std::size_t nc = tree_.cells.size();
  M_.assign(nc * fmm::tri_size(p_), {});
  Lc_.assign(nc * fmm::tri_size(p_), {});
  Mre_.assign(nc * ncoef(p_), 0.0);
  Mim_.assign(nc * ncoef(p_), 0.0);
}

// Symmetric dual-tree traversal from (root, root): accepted pairs go into both M2L lists, pairs of
// leaves into the near pairs, otherwise the larger (non-leaf) cell is split.
void SphereFarField::classify(double theta) {
  m2l_.assign(tree_.cells.size(), {});
  near_.clear();
  if (tree_.cells.empty()) return;
  auto near_leaves = [&](const fmm::Cell& a, const fmm::Cell& b, bool same) {
    for (int i = a.begin; i < a.end; ++i)
      for (int k = same ? i + 1 : b.begin; k < b.end; ++k) {
        const int oi = tree_.order[i], ok = tree_.order[k];
        near_.push_back({std::min(oi, ok), std::max(oi, ok)});
      }
  };
  std::vector<std::array<int, 2>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [ia, ib] = stack.back();
    stack.pop_back();
    const fmm::Cell& a = tree_.cells[ia];
    const fmm::Cell& b = tree_.cells[ib];
    if (ia == ib) {
      if (a.leaf()) near_leaves(a, a, true);
      for (int c1 = a.child; c1 < a.child + a.nchild; ++c1)
        for (int c2 = c1; c2 < a.child + a.nchild; ++c2) stack.push_back({c1, c2});
    } else if (a.radius + b.radius < theta * norm(a.center - b.center)) {
      m2l_[ia].push_back(ib);
      m2l_[ib].push_back(ia);
      n_m2l_ += 2;
    } else if (a.leaf() && b.leaf()) {
      near_leaves(a, b, false);
    } else if (b.leaf() || (!a.leaf() && a.radius >= b.radius)) {
      for (int c = a.child; c < a.child + a.nchild; ++c) stack.push_back({c, ib});
    } else {
      for (int c = b.child; c < b.child + b.nchild; ++c) stack.push_back({ia, c});
    }
  }
  std::sort(near_.begin(), near_.end());
}

// Cell multipoles: spheres into their leaf, children into parents, deepest level first.
void SphereFarField::upward(const double* beta) const {
  const int ts = fmm::tri_size(p_), nc = ncoef(L_);
  std::fill(M_.begin(), M_.end(), fmm::cplx(0.0, 0.0));
  for (int lev = tree_.levels() - 1; lev >= 0; --lev) {
    const int c0 = tree_.level_begin[lev], c1 = tree_.level_begin[lev + 1];
#pragma omp parallel if (std::size_t(c1 - c0) >= kParallelCells)
    {
      fmm::OperatorScratch scratch(p_);
      std::vector<fmm::cplx> Ms(ts);
#pragma omp for schedule(dynamic, 4)
      for (int c = c0; c < c1; ++c) {
        const fmm::Cell& cell = tree_.cells[c];
        fmm::cplx* Mc = &M_[std::size_t(c) * ts];
        if (cell.leaf()) {
          for (int k = cell.begin; k < cell.end; ++k) {
            basis_.multipole_from_real(L_, rho_[k], beta + std::size_t(tree_.order[k]) * nc, Ms.data());
            fmm::m2m(Ms.data(), sorted_point(tree_, k) - cell.center, p_, Mc, scratch);
          }
        } else {
          for (int ch = cell.child; ch < cell.child + cell.nchild; ++ch)
            fmm::m2m(&M_[std::size_t(ch) * ts], tree_.cells[ch].center - cell.center, p_, Mc, scratch);
        }
      }
    }
  }
}

// M2L of every accepted source cell into each target cell's local expansion.
void SphereFarField::interact() const {
  const int ts = fmm::tri_size(p_), fs = ncoef(p_);
  const int ncell = static_cast<int>(tree_.cells.size());
  const bool threaded = parallel();
#pragma omp parallel for schedule(static) if (threaded)
  for (int c = 0; c < ncell; ++c)
    fmm::split_multipole(&M_[std::size_t(c) * ts], p_, &Mre_[std::size_t(c) * fs], &Mim_[std::size_t(c) * fs]);
  std::fill(Lc_.begin(), Lc_.end(), fmm::cplx(0.0, 0.0));
#pragma omp parallel if (threaded)
  {
    fmm::OperatorScratch scratch(p_);
#pragma omp for schedule(dynamic, 2)
    for (int c = 0; c < ncell; ++c)
      for (int b : m2l_[c])
        fmm::m2l(&Mre_[std::size_t(b) * fs], &Mim_[std::size_t(b) * fs], tree_.cells[c].center - tree_.cells[b].center,
                 p_, &Lc_[std::size_t(c) * ts], scratch);
  }
}

// Locals down the tree (L2L), then from each leaf to its spheres' centres, added to alpha.
void SphereFarField::downward(double* alpha) const {
  const int ts = fmm::tri_size(p_), nc = ncoef(L_);
  for (int lev = 1; lev < tree_.levels(); ++lev) {
    const int c0 = tree_.level_begin[lev], c1 = tree_.level_begin[lev + 1];
#pragma omp parallel if (std::size_t(c1 - c0) >= kParallelCells)
    {
      fmm::OperatorScratch scratch(p_);
#pragma omp for schedule(dynamic, 4)
      for (int c = c0; c < c1; ++c) {
        const fmm::Cell& cell = tree_.cells[c];
        fmm::l2l(&Lc_[std::size_t(cell.parent) * ts], cell.center - tree_.cells[cell.parent].center, p_,
                 &Lc_[std::size_t(c) * ts], scratch);
      }
    }
  }
  const int ncell = static_cast<int>(tree_.cells.size());
#pragma omp parallel if (std::size_t(ncell) >= kParallelCells)
  {
    fmm::OperatorScratch scratch(p_);
    std::vector<fmm::cplx> Ls(ts);
#pragma omp for schedule(dynamic, 4)
    for (int c = 0; c < ncell; ++c) {
      const fmm::Cell& cell = tree_.cells[c];
      if (!cell.leaf()) continue;
      for (int k = cell.begin; k < cell.end; ++k) {
        std::fill(Ls.begin(), Ls.end(), fmm::cplx(0.0, 0.0));
        fmm::l2l(&Lc_[std::size_t(c) * ts], sorted_point(tree_, k) - cell.center, p_, Ls.data(), scratch);
        basis_.add_real_local(L_, rho_[k], Ls.data(), alpha + std::size_t(tree_.order[k]) * nc);
      }
    }
  }
}

void SphereFarField::add(const double* beta, double* alpha) const {
  if (n_m2l_ == 0) return;
  upward(beta);
  poll_cancel();
  interact();
  poll_cancel();
  downward(alpha);
  poll_cancel();
}

}  // namespace agglo::es::sh
