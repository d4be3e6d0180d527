#include "agglo/acoustics/initial_placement.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "agglo/acoustics/case_config.hpp"
#include "agglo/core/rng.hpp"

namespace agglo::acoustics {

namespace {
// Philox streams of the initial state: positions (as in every earlier version) and cell permutations.
constexpr std::uint64_t kPositionStream = 0x9000000000ULL;
constexpr std::uint64_t kPermutationStream = 0xA000000000ULL;

// Coordinate along one axis uniformly inside cell `cell` of `cells` on [0, L): the binning of the
// engine (int(x cells / L)) must give `cell` back, so round-off at the cell faces is corrected.
double inside_cell(double u, int cell, int cells, double L) {
  const double f = cells / L;
  // The largest double below L: nextafter(L, 0) of a positive finite L is the bit pattern one below.
  const double below_L = L > 0.0 && std::isfinite(L) ? std::bit_cast<double>(std::bit_cast<std::uint64_t>(L) - 1)
                                                     : std::nextafter(L, 0.0);
  double x = std::min((cell + u) * (L / cells), below_L);
  while (x > 0.0 && static_cast<int>(x * f) > cell) x = std::nextafter(x, 0.0);
  while (static_cast<int>(x * f) < cell) x = std::nextafter(x, L);
  return x;
}

// Random permutation of the cells for round r (Fisher-Yates).
void permute_cells(std::vector<std::uint32_t>& perm, std::uint64_t seed, int population, std::uint64_t r) {
  std::iota(perm.begin(), perm.end(), 0u);
  CounterRng rng(seed, kPermutationStream + static_cast<std::uint64_t>(population), r);
  for (std::size_t i = perm.size(); i > 1; --i) {
    const auto j = static_cast<std::size_t>(rng.uniform() * static_cast<double>(i));
    std::swap(perm[i - 1], perm[std::min(j, i - 1)]);
  }
}
}  // namespace

std::int64_t clone_factor(std::int64_t samples, std::int64_t cells, std::int64_t min_samples_per_cell) {
  const std::int64_t want = min_samples_per_cell * cells;
  if (samples <= 0 || samples >= want) return 1;
  return (want + samples - 1) / samples;
}

std::size_t sample_count_after_cloning(const AcousticCase& c) {
  const auto& e = c.engine;
  const std::int64_t cells = e.motion.domain.num_cells();
  std::size_t n = 0;
  for (const auto& p : e.populations)
    n += static_cast<std::size_t>(p.samples * clone_factor(p.samples, cells, e.sampling.min_samples_per_cell));
  return n;
}

std::size_t split_into_clones(SampleSet& p, std::size_t first, std::size_t count, std::int64_t k) {
  if (k <= 1 || count == 0) return count;
  std::vector<std::int64_t> kk(count);  // clones of each sample: min(k, w), so every clone has weight >= 1
  std::size_t total = 0;
  for (std::size_t m = 0; m < count; ++m) {
    kk[m] = std::max<std::int64_t>(1, std::min<std::int64_t>(k, std::llround(p.w[first + m])));
    total += static_cast<std::size_t>(kk[m]);
  }
  p.resize(first + total);
  // Expand from the back: the clones of sample m go to [dst, dst + kk[m]) with dst >= first + m.
  std::size_t dst = first + total;
  for (std::size_t m = count; m-- > 0;) {
    const std::size_t src = first + m;
    const std::int64_t w = std::llround(p.w[src]), q = w / kk[m], extra = w % kk[m];
    dst -= static_cast<std::size_t>(kk[m]);
    for (std::int64_t j = kk[m] - 1; j >= 0; --j) {
      const std::size_t to = dst + static_cast<std::size_t>(j);
      if (to != src) p.copy_sample(src, to);
      p.id[to] = p.id[src];
      p.w[to] = static_cast<double>(q + (j < extra ? 1 : 0));
    }
  }
  return total;
}

void place_samples(SampleSet& p, std::size_t first, std::size_t count, Placement placement, const Domain& dom,
                   std::uint64_t seed, int population) {
  const std::uint64_t stream = kPositionStream + static_cast<std::uint64_t>(population);
  const auto cells = static_cast<std::size_t>(dom.num_cells());
  std::vector<std::uint32_t> perm(placement == Placement::stratified ? cells : 0);
  for (std::size_t m = 0; m < count; ++m) {
    CounterRng rng(seed, stream, m);
    const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
    double* pos[3] = {&p.x[first + m], &p.y[first + m], &p.z[first + m]};
    if (placement == Placement::random) {
      *pos[0] = u0 * dom.L[0];
      *pos[1] = u1 * dom.L[1];
      *pos[2] = u2 * dom.L[2];
      continue;
    }
    if (m % cells == 0) permute_cells(perm, seed, population, m / cells);
    const std::uint32_t c = perm[m % cells];
    const int cx = static_cast<int>(c % static_cast<std::uint32_t>(dom.cells[0]));
    const int cyz = static_cast<int>(c / static_cast<std::uint32_t>(dom.cells[0]));
    const int cy = cyz % dom.cells[1], cz = cyz / dom.cells[1];
    *pos[0] = inside_cell(u0, cx, dom.cells[0], dom.L[0]);
    *pos[1] = inside_cell(u1, cy, dom.cells[1], dom.L[1]);
    *pos[2] = inside_cell(u2, cz, dom.cells[2], dom.L[2]);
  }
}

}  // namespace agglo::acoustics
