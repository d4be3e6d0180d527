#include "agglo/dem/contact/pair_blocks.hpp"

#include <algorithm>

namespace agglo::dem::contact {

PairBlocks make_pair_blocks(const std::vector<Pair>& pairs, std::size_t n_particles, std::size_t blocks) {
  const std::size_t np = pairs.size();
  // (the order argument needs i < j and pairs sorted by i; otherwise one block, the serial order)
  bool ordered = true;
  for (std::size_t k = 0; k < np && ordered; ++k)
    ordered = pairs[k].i < pairs[k].j && (k == 0 || pairs[k - 1].i <= pairs[k].i);
  const std::size_t nb = ordered ? std::max<std::size_t>(1, blocks) : 1;
  PairBlocks b;
  b.first_particle.assign(nb + 1, static_cast<std::uint32_t>(n_particles));
  b.first_pair.assign(nb + 1, np);
  b.first_particle[0] = 0;
  b.first_pair[0] = 0;
  for (std::size_t t = 1; t < nb; ++t) {
    const std::size_t k = t * np / nb;
    const std::uint32_t first = std::max(k < np ? pairs[k].i : static_cast<std::uint32_t>(n_particles),
                                         b.first_particle[t - 1]);
    b.first_particle[t] = first;
    b.first_pair[t] = static_cast<std::size_t>(
        std::lower_bound(pairs.begin(), pairs.end(), first, [](const Pair& p, std::uint32_t i) { return p.i < i; }) -
        pairs.begin());
  }
  b.crossing_in.assign(nb, {});
  for (std::size_t t = 0; t < nb; ++t)
    for (std::size_t k = b.first_pair[t]; k < b.first_pair[t + 1]; ++k) {
      const std::uint32_t j = pairs[k].j;
      if (j < b.first_particle[t + 1]) continue;
      const auto owner = std::upper_bound(b.first_particle.begin(), b.first_particle.end(), j) - b.first_particle.begin() - 1;
      b.crossing.push_back(k);
      b.crossing_in[static_cast<std::size_t>(owner)].push_back(k);
    }
  return b;
}

}  // namespace agglo::dem::contact
