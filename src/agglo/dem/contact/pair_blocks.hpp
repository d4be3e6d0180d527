#pragma once
// The listed pairs (sorted by (i, j), neighbor_list.hpp) split into B blocks for B threads, so that the
// pair forces can be added straight into the particles on several threads with the sums of the serial
// loop (contact_kernel.hpp, accumulate_pairs), bit for bit:
//   block b owns the particles [first_particle[b], first_particle[b+1]) and the pairs whose i it owns,
//   [first_pair[b], first_pair[b+1]) (chosen so that the blocks own about equal numbers of pairs with both
//   particles in the block; a particle's pairs as i stay in one block);
//   a pair whose j lies beyond its block's particles is a crossing pair: its force is computed first into
//   a buffer (phase 1: all crossing pairs, split evenly over the threads whatever their blocks) and added
//   to j by j's block before that block's own pairs (phase 2, one block per thread). In the serial order the pairs
//   that touch an owned particle from an earlier block all come before the block's own pairs (their i is
//   smaller), so every particle receives the same terms in the same order.
// No physics: bookkeeping of the parallel pair step (docs/benchmarks_dem.md §5).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "agglo/dem/neighbor_list.hpp"

namespace agglo::dem::contact {

struct PairBlocks {
  std::vector<std::uint32_t> first_particle;  // B + 1 bounds
  std::vector<std::size_t> first_pair;        // B + 1 bounds
  std::vector<std::size_t> crossing;                   // every crossing pair, ascending
  std::vector<std::vector<std::size_t>> crossing_in;   // per block: the crossing pairs whose j it owns, ascending
  std::size_t blocks() const { return first_pair.empty() ? 0 : first_pair.size() - 1; }
};

// Blocks of `pairs` (sorted by (i, j)) over n_particles particles, B >= 1 of them.
PairBlocks make_pair_blocks(const std::vector<Pair>& pairs, std::size_t n_particles, std::size_t blocks);

}  // namespace agglo::dem::contact
