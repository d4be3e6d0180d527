#include "agglo/electrostatics/fmm/octree.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace agglo::es::fmm {

namespace {
constexpr int kMaxDepth = 40;

void fit_cell(Cell& c, const Points& s) {
  Vec3 lo{s.x[c.begin], s.y[c.begin], s.z[c.begin]}, hi = lo;
  for (int k = c.begin; k < c.end; ++k) {
    lo = {std::min(lo.x, s.x[k]), std::min(lo.y, s.y[k]), std::min(lo.z, s.z[k])};
    hi = {std::max(hi.x, s.x[k]), std::max(hi.y, s.y[k]), std::max(hi.z, s.z[k])};
  }
  c.center = 0.5 * (lo + hi);
  double r2 = 0.0;
  for (int k = c.begin; k < c.end; ++k)
    r2 = std::max(r2, norm2(Vec3{s.x[k], s.y[k], s.z[k]} - c.center));
  c.radius = std::sqrt(r2);
}
}  // namespace

Octree::Octree(std::span<const Vec3> points, int leaf_size) {
  const int n = static_cast<int>(points.size());
  leaf_size = std::max(leaf_size, 1);
  order.resize(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  level_begin.clear();
  if (n == 0) {
    level_begin = {0};
    return;
  }
  sorted = Points(points);
  // Cube of each cell (for octant splitting), parallel to `cells`.
  std::vector<Vec3> box_center;
  std::vector<double> box_half;
  Cell root;
  root.begin = 0;
  root.end = n;
  fit_cell(root, sorted);
  Vec3 lo{sorted.x[0], sorted.y[0], sorted.z[0]}, hi = lo;
  for (int k = 0; k < n; ++k) {
    lo = {std::min(lo.x, sorted.x[k]), std::min(lo.y, sorted.y[k]), std::min(lo.z, sorted.z[k])};
    hi = {std::max(hi.x, sorted.x[k]), std::max(hi.y, sorted.y[k]), std::max(hi.z, sorted.z[k])};
  }
  cells.push_back(root);
  box_center.push_back(0.5 * (lo + hi));
  box_half.push_back(0.5 * std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z}) * (1 + 1e-12) + 1e-300);

  std::vector<int> tmp;
  std::vector<int> oct;
  for (std::size_t ci = 0; ci < cells.size(); ++ci) {
    if (cells[ci].level == static_cast<int>(level_begin.size())) level_begin.push_back(static_cast<int>(ci));
    const int b = cells[ci].begin, e = cells[ci].end;
    if (e - b <= leaf_size || cells[ci].level >= kMaxDepth) continue;
    const Vec3 bc = box_center[ci];
    const double h = box_half[ci];
    // Counting sort of [b, e) into octants.
    std::array<int, 9> start{};
    oct.resize(e - b);
    for (int k = b; k < e; ++k) {
      const int o = (sorted.x[k] >= bc.x) | ((sorted.y[k] >= bc.y) << 1) | ((sorted.z[k] >= bc.z) << 2);
      oct[k - b] = o;
      ++start[o + 1];
    }
    for (int o = 0; o < 8; ++o) start[o + 1] += start[o];
    tmp.resize(e - b);
    std::array<int, 8> pos{};
    for (int o = 0; o < 8; ++o) pos[o] = start[o];
    for (int k = b; k < e; ++k) tmp[pos[oct[k - b]]++] = order[k];
    for (int k = b; k < e; ++k) {
      order[k] = tmp[k - b];
      sorted.x[k] = points[order[k]].x;
      sorted.y[k] = points[order[k]].y;
      sorted.z[k] = points[order[k]].z;
    }
    const int first = static_cast<int>(cells.size());
    int nchild = 0;
    for (int o = 0; o < 8; ++o) {
      if (start[o + 1] == start[o]) continue;
      Cell c;
      c.begin = b + start[o];
      c.end = b + start[o + 1];
      c.parent = static_cast<int>(ci);
      c.level = cells[ci].level + 1;
      fit_cell(c, sorted);
      const double hh = 0.5 * h;
      box_center.push_back(bc + Vec3{(o & 1) ? hh : -hh, (o & 2) ? hh : -hh, (o & 4) ? hh : -hh});
      box_half.push_back(hh);
      cells.push_back(c);
      ++nchild;
    }
    cells[ci].child = first;
    cells[ci].nchild = nchild;
  }
  level_begin.push_back(static_cast<int>(cells.size()));
}

InteractionLists build_interaction_lists(const Octree& T, const Octree& S, double theta) {
  InteractionLists L;
  const std::size_t nt = T.cells.size();
  L.m2l.resize(nt);
  L.p2p.resize(nt);
  if (nt == 0 || S.cells.empty()) return L;
  std::vector<std::vector<int>> pending(nt);
  pending[0] = {0};
  for (int lev = 0; lev < T.levels(); ++lev) {
    const int c0 = T.level_begin[lev], c1 = T.level_begin[lev + 1];
#pragma omp parallel for schedule(dynamic, 4)
    for (int c = c0; c < c1; ++c) {
      const Cell& a = T.cells[c];
      std::vector<int> work = std::move(pending[c]);
      while (!work.empty()) {
        const int bi = work.back();
        work.pop_back();
        const Cell& b = S.cells[bi];
        const double d = norm(a.center - b.center);
        if (a.radius + b.radius < theta * d) {
          L.m2l[c].push_back(bi);
        } else if (a.leaf()) {
          if (b.leaf())
            L.p2p[c].push_back(bi);
          else
            for (int k = 0; k < b.nchild; ++k) work.push_back(b.child + k);
        } else if (b.leaf() || a.radius >= b.radius) {
          for (int k = 0; k < a.nchild; ++k) pending[a.child + k].push_back(bi);
        } else {
          for (int k = 0; k < b.nchild; ++k) work.push_back(b.child + k);
        }
      }
    }
  }
  for (std::size_t c = 0; c < nt; ++c) {
    L.n_m2l += L.m2l[c].size();
    L.n_p2p += L.p2p[c].size();
  }
  return L;
}

}  // namespace agglo::es::fmm
