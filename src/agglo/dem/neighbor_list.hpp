#pragma once
// Verlet pair list built from a uniform cell grid (O(N)). Pairs (i < j) whose surfaces are within
// `skin` of each other are listed; the list is rebuilt when any particle has moved more than
// skin/2 since the last build. Contact states travel with their pair across rebuilds.
#include <cstdint>
#include <functional>
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/dem/contact/pair_state.hpp"
#include "agglo/dem/jkr.hpp"

namespace agglo::dem {

struct NeighborState;

struct Pair {
  std::uint32_t i = 0, j = 0;
  ContactState state;
  std::uint32_t kind = 0;  // material pair (MaterialPairs::kind of the two material ids)
  JkrPair jkr;  // per-pair JKR constants (depend on the radii and the materials)
};

class NeighborList {
 public:
  // Rebuild from positions/radii; carries the states of pairs that stay listed.
  // Active contacts are always kept even if they moved beyond the list range.
  void build(const std::vector<Vec3>& x, const std::vector<double>& r, double skin,
             const std::function<void(Pair&)>& init_pair);  // sets kind and jkr of a new pair (i, j)
  bool needs_rebuild(const std::vector<Vec3>& x, double skin) const;
  // The same test one particle at a time (DemSystem::step folds it into its drift loop): whether the list
  // was built for n particles, and whether particle p at x moved more than sqrt(lim2) = skin / 2 since.
  bool built_for(std::size_t n) const { return x_at_build_.size() == n; }
  bool moved_beyond(std::size_t p, const Vec3& x, double lim2) const { return norm2(x - x_at_build_[p]) > lim2; }
  const std::vector<Vec3>& positions_at_build() const { return x_at_build_; }  // (the same test on a range)

  std::vector<Pair>& pairs() { return pairs_; }
  const std::vector<Pair>& pairs() const { return pairs_; }
  // CSR: pairs touching particle p are entries [offset[p], offset[p+1]) of `index`;
  // a non-negative entry k means p is pair k's i, ~k (negative) means p is pair k's j.
  const std::vector<std::int64_t>& offsets() const { return offset_; }
  const std::vector<std::int64_t>& entries() const { return index_; }
  long builds() const { return builds_; }

  // Checkpoint state (the adjacency is rebuilt from the pairs); defined in dem_state.cpp.
  NeighborState state() const;
  void restore(const NeighborState& s, std::size_t n_particles);

 private:
  void index(std::size_t n);  // CSR adjacency of pairs_ for n particles
  std::vector<Pair> pairs_;
  std::vector<Vec3> x_at_build_;
  std::vector<std::int64_t> offset_, index_;
  long builds_ = 0;
};

}  // namespace agglo::dem
