#include "agglo/dem/contact/pair_blocks.hpp"

#include <algorithm>

namespace agglo::dem::contact {

namespace {

// First particles of nb blocks of `pairs` (sorted by i) such that each block but the last owns `target`
// pairs (both particles in the block) or just more: block t ends at the first particle s at which the pairs
// with i in [start, s) and j < s reach the target. Moving the end from s to s + 1 makes own the block's pairs
// with j = s (counted in pending[s] as their i is passed); the pairs of i = s have j > s. Linear in the pairs.
std::vector<std::uint32_t> own_balanced_bounds(const std::vector<Pair>& pairs, std::size_t n, std::size_t nb,
                                               std::size_t target) {
  std::vector<std::uint32_t> first(nb + 1, static_cast<std::uint32_t>(n));
  first[0] = 0;
  std::vector<std::uint32_t> pending(n, 0);
  std::size_t k = 0;
  for (std::size_t t = 1; t < nb; ++t) {
    const std::size_t k_start = k;
    std::uint32_t s = first[t - 1];
    for (std::size_t own = 0; s < n && own < target; ++s) {
      own += pending[s];
      pending[s] = 0;
      for (; k < pairs.size() && pairs[k].i == s; ++k) ++pending[pairs[k].j];
    }
    for (std::size_t c = k_start; c < k; ++c) pending[pairs[c].j] = 0;  // (the block's crossing pairs)
    first[t] = s;
  }
  return first;
}

// The pair ranges and the crossing lists of the blocks whose first particles b.first_particle holds.
void assign_pairs(PairBlocks& b, const std::vector<Pair>& pairs) {
  const std::size_t nb = b.first_particle.size() - 1;
  b.first_pair.assign(nb + 1, pairs.size());
  for (std::size_t t = 0; t < nb; ++t)
    b.first_pair[t] = static_cast<std::size_t>(
        std::lower_bound(pairs.begin(), pairs.end(), b.first_particle[t],
                         [](const Pair& p, std::uint32_t i) { return p.i < i; }) -
        pairs.begin());
  b.crossing.clear();
  b.crossing_in.assign(nb, {});
  for (std::size_t t = 0; t < nb; ++t)
    for (std::size_t k = b.first_pair[t]; k < b.first_pair[t + 1]; ++k) {
      const std::uint32_t j = pairs[k].j;
      if (j < b.first_particle[t + 1]) continue;
      const auto owner = std::upper_bound(b.first_particle.begin(), b.first_particle.end(), j) - b.first_particle.begin() - 1;
      b.crossing.push_back(k);
      b.crossing_in[static_cast<std::size_t>(owner)].push_back(k);
    }
}

}  // namespace

PairBlocks make_pair_blocks(const std::vector<Pair>& pairs, std::size_t n_particles, std::size_t blocks) {
  const std::size_t np = pairs.size();
  // (the order argument needs i < j and pairs sorted by i; otherwise one block, the serial order)
  bool ordered = true;
  for (std::size_t k = 0; k < np && ordered; ++k)
    ordered = pairs[k].i < pairs[k].j && (k == 0 || pairs[k - 1].i <= pairs[k].i);
  const std::size_t nb = ordered ? std::max<std::size_t>(1, blocks) : 1;
  PairBlocks b;
  // Phase 1 spreads the crossing pairs evenly, so phase 2 is balanced when the blocks own equal numbers of
  // pairs: a first split for np / nb own pairs each gives the crossing count C, the second for (np - C) / nb.
  b.first_particle = own_balanced_bounds(pairs, n_particles, nb, np / nb);
  assign_pairs(b, pairs);
  b.first_particle = own_balanced_bounds(pairs, n_particles, nb, (np - b.crossing.size()) / nb);
  assign_pairs(b, pairs);
  return b;
}

}  // namespace agglo::dem::contact
