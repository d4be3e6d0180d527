#pragma once
// Adaptive octree for the FMM: cells are split into octants until they hold at most
// `leaf_size` points. Cells are stored breadth-first (so a level is a contiguous range and the
// children of a cell are contiguous); points are permuted into cell order.
// Each cell's expansion centre is the centre of the tight bounding box of its points and its
// radius the largest distance from that centre to one of its points (tight for surfaces).
#include <span>
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/electrostatics/fmm/direct.hpp"

namespace agglo::es::fmm {

struct Cell {
  Vec3 center;        // expansion centre
  double radius = 0;  // max |x - center| over the cell's points
  int begin = 0, end = 0;        // range in sorted point order
  int child = -1, nchild = 0;    // first child, number of children (0 = leaf)
  int parent = -1, level = 0;
  bool leaf() const { return nchild == 0; }
};

class Octree {
 public:
  Octree() = default;
  Octree(std::span<const Vec3> points, int leaf_size);

  std::vector<Cell> cells;        // cells[0] = root (if any point)
  std::vector<int> order;         // sorted slot k -> original point index
  std::vector<int> level_begin;   // cells of level l: [level_begin[l], level_begin[l+1])
  Points sorted;                  // coordinates in sorted order
  int levels() const { return static_cast<int>(level_begin.size()) - 1; }
};

// Dual-tree interaction lists for target tree T and source tree S (may be the same object).
// Multipole acceptance: r_T + r_S < theta |c_T - c_S|  -> M2L; both leaves otherwise -> P2P;
// else the larger cell is split. Built top-down per target cell (OpenMP over a level).
struct InteractionLists {
  std::vector<std::vector<int>> m2l;  // per target cell: source cells
  std::vector<std::vector<int>> p2p;  // per target leaf: source leaves
  std::size_t n_m2l = 0, n_p2p = 0;   // totals
};

InteractionLists build_interaction_lists(const Octree& T, const Octree& S, double theta);

}  // namespace agglo::es::fmm
