#include "agglo/acoustics/collision_step.hpp"

#include <algorithm>

namespace agglo::acoustics {

void CollisionStats::add(const CollisionStats& o) {
  trials += o.trials;
  kernel_evals += o.kernel_evals;
  collisions += o.collisions;
  for (int k = 0; k < 3; ++k) {
    coalescences[k] += o.coalescences[k];
    rebounds[k] += o.rebounds[k];
    breakups[k] += o.breakups[k];
  }
  particle_steps += o.particle_steps;
  subcycled += o.subcycled;
  max_subcycles = std::max(max_subcycles, o.max_subcycles);
  max_bound_pn = std::max(max_bound_pn, o.max_bound_pn);
  max_pn = std::max(max_pn, o.max_pn);
  violations += o.violations;
  refills += o.refills;
  dead += o.dead;
  energy_lost += o.energy_lost;
  energy_returned += o.energy_returned;
  row_rate_updates += o.row_rate_updates;
  table_queries += o.table_queries;
  table_clamped += o.table_clamped;
  table_turned_back += o.table_turned_back;
  wet_table_queries += o.wet_table_queries;
  wet_table_clamped += o.wet_table_clamped;
  wet_table_turned_back += o.wet_table_turned_back;
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(AGGLO_NO_AVX2)
__attribute__((target_clones("avx2", "default")))
#endif
std::size_t count_positive(const double* v, const std::uint32_t* idx, std::size_t begin, std::size_t end) {
  std::size_t k = 0;
  for (std::size_t a = begin; a < end; ++a) k += v[idx[a]] > 0.0 ? 1 : 0;
  return k;
}

}  // namespace agglo::acoustics
