#include "agglo/dem/neighbor_list.hpp"

#include <algorithm>
#include <cmath>

namespace agglo::dem {

bool NeighborList::needs_rebuild(const std::vector<Vec3>& x, double skin) const {
  if (x.size() != x_at_build_.size()) return true;
  const double lim2 = 0.25 * skin * skin;
  for (std::size_t p = 0; p < x.size(); ++p)
    if (moved_beyond(p, x[p], lim2)) return true;
  return false;
}

namespace {

using IndexPair = std::pair<std::uint32_t, std::uint32_t>;

// The found pairs (p, q) ordered by p, each p's partners sorted: a counting sort by p (stable), then each
// p's few partners sorted on their own (no sort of the whole list).
std::vector<IndexPair> sorted_by_first(const std::vector<IndexPair>& found, std::size_t n) {
  std::vector<std::size_t> start(n + 1, 0);
  for (const auto& [p, q] : found) ++start[p + 1];
  for (std::size_t p = 0; p < n; ++p) start[p + 1] += start[p];
  std::vector<IndexPair> out(found.size());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const auto& pq : found) out[fill[pq.first]++] = pq;
  for (std::size_t p = 0; p < n; ++p)
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(start[p]), out.begin() + static_cast<std::ptrdiff_t>(start[p + 1]));
  return out;
}

// The pairs (p, q), p < q, closer than r_p + r_q + skin, sorted: a sparse cell grid of cells 2 rmax + skin
// wide. Sparse: the (cell key, particle) pairs sorted by key keep memory O(N) for far-flung particles (one
// allocation); the cells (a, b, c - 1 .. c + 1) of one row have consecutive keys, one range. The particles
// are visited in key order, so each of the nine rows' ranges only moves forward: one cursor per row
// instead of a binary search per particle and row.
std::vector<IndexPair> close_pairs(const std::vector<Vec3>& x, const std::vector<double>& r, double skin) {
  const std::size_t n = x.size();
  std::vector<IndexPair> found;
  if (n < 2) return found;
  double rmax = *std::max_element(r.begin(), r.end());
  Vec3 lo = x[0], hi = x[0];
  for (const auto& p : x)
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], p[c]);
      hi[c] = std::max(hi[c], p[c]);
    }
  const double cell = 2.0 * rmax + skin;
  std::int64_t dims[3];
  for (int c = 0; c < 3; ++c) dims[c] = std::max<std::int64_t>(1, static_cast<std::int64_t>((hi[c] - lo[c]) / cell) + 1);
  auto key = [&](std::int64_t a, std::int64_t b, std::int64_t c) { return (a * dims[1] + b) * dims[2] + c; };
  std::vector<std::int64_t> ci(n * 3);
  std::vector<std::pair<std::int64_t, std::uint32_t>> bins(n);
  for (std::size_t p = 0; p < n; ++p) {
    for (int c = 0; c < 3; ++c) ci[3 * p + c] = static_cast<std::int64_t>((x[p][c] - lo[c]) / cell);
    bins[p] = {key(ci[3 * p], ci[3 * p + 1], ci[3 * p + 2]), static_cast<std::uint32_t>(p)};
  }
  std::sort(bins.begin(), bins.end());
  // Row (a + da, b + db) of cell (a, b, c) starts at key(a, b, c) + (da dims[1] + db) dims[2] + (c_lo - c).
  std::int64_t row_offset[9];
  for (int row = 0; row < 9; ++row) row_offset[row] = ((row / 3 - 1) * dims[1] + (row % 3 - 1)) * dims[2];
  std::size_t cursor[9] = {};
  for (const auto& kp : bins) {
    const std::uint32_t p = kp.second;
    const std::int64_t a = ci[3 * p], b = ci[3 * p + 1], c = ci[3 * p + 2];
    const std::int64_t lo_shift = c > 0 ? -1 : 0, hi_shift = c + 1 < dims[2] ? 1 : 0;
    const bool a_ok[3] = {a > 0, true, a + 1 < dims[0]}, b_ok[3] = {b > 0, true, b + 1 < dims[1]};
    for (int da = 0; da < 3; ++da) {
      if (!a_ok[da]) continue;
      for (int db = 0; db < 3; ++db) {
        if (!b_ok[db]) continue;
        const int row = 3 * da + db;
        const std::int64_t k_lo = kp.first + row_offset[row] + lo_shift, k_hi = kp.first + row_offset[row] + hi_shift;
        std::size_t& it = cursor[row];
        while (it < n && bins[it].first < k_lo) ++it;
        for (std::size_t s = it; s < n && bins[s].first <= k_hi; ++s) {
          const std::uint32_t q = bins[s].second;
          if (q <= p) continue;
          const double lim = r[p] + r[q] + skin;
          if (norm2(x[q] - x[p]) < lim * lim) found.emplace_back(p, q);
        }
      }
    }
  }
  return sorted_by_first(found, n);
}

}  // namespace

void NeighborList::build(const std::vector<Vec3>& x, const std::vector<double>& r, double skin,
                         const std::function<void(Pair&)>& init_pair) {
  const std::size_t n = x.size();
  ++builds_;
  x_at_build_ = x;
  const std::vector<IndexPair> close = close_pairs(x, r, skin);
  // Keep active contacts that drifted out of range (they are still bonded): the old list is sorted (a list
  // restored from elsewhere is sorted here first), so its active pairs are, and the two sorted lists merge.
  const auto by_index = [](const Pair& a, const Pair& b) {
    return std::make_pair(a.i, a.j) < std::make_pair(b.i, b.j);
  };
  if (!std::is_sorted(pairs_.begin(), pairs_.end(), by_index)) std::sort(pairs_.begin(), pairs_.end(), by_index);
  std::vector<IndexPair> bonded;
  for (const auto& pr : pairs_)
    if (pr.state.active) bonded.emplace_back(pr.i, pr.j);
  std::vector<IndexPair> found(close.size() + bonded.size());
  std::merge(close.begin(), close.end(), bonded.begin(), bonded.end(), found.begin());
  found.erase(std::unique(found.begin(), found.end()), found.end());

  // Merge states from the old (sorted) list.
  std::vector<Pair> fresh;
  fresh.reserve(found.size());
  std::size_t k = 0;
  for (const auto& [i, j] : found) {
    while (k < pairs_.size() && std::make_pair(pairs_[k].i, pairs_[k].j) < std::make_pair(i, j)) ++k;
    if (k < pairs_.size() && pairs_[k].i == i && pairs_[k].j == j) {
      fresh.push_back(pairs_[k]);
    } else {
      Pair p;
      p.i = i;
      p.j = j;
      init_pair(p);
      fresh.push_back(p);
    }
  }
  pairs_.swap(fresh);
  index(n);
}

void NeighborList::index(std::size_t n) {
  offset_.assign(n + 1, 0);
  for (const auto& p : pairs_) {
    ++offset_[p.i + 1];
    ++offset_[p.j + 1];
  }
  for (std::size_t p = 0; p < n; ++p) offset_[p + 1] += offset_[p];
  index_.assign(offset_[n], 0);
  std::vector<std::int64_t> fill(offset_.begin(), offset_.end() - 1);
  for (std::size_t kk = 0; kk < pairs_.size(); ++kk) {
    index_[fill[pairs_[kk].i]++] = static_cast<std::int64_t>(kk);
    index_[fill[pairs_[kk].j]++] = ~static_cast<std::int64_t>(kk);
  }
}

}  // namespace agglo::dem
