#pragma once
// Weighted collision processing between two samples (docs/model.md §C.5; Zhao et al. 2023, section 2.5).
// Coalescence conserves volume, mass and momentum (eqs. 15-17); solid and liquid volumes add
// separately. Weights (eqs. 18-21):
//   w_i = w_j even -> both w/2, both merged;   w_i = w_j odd -> (w+1)/2 and (w-1)/2, both merged;
//   w_i > w_j -> i keeps its state with w_i - w_j, j becomes merged with w_j (mirror for w_i < w_j).
// Non-integer equal weights are halved.
// Aggregate structure (structure.hpp, runs with a fractal population): the merged particle holds
// n_i + n_j primaries, of the common primary radius or else of the cube-mean radius.
// Rebound: equal weights -> hard-sphere rebound (eqs. 22-23, 26); unequal weights -> split-merge
// (eqs. 25, 27-28): the heavier sample i is split into i* (w_j) and i** (w_i - w_j), i* and j
// rebound, then i* and i** merge by momentum. The kinetic energy lost by that merge (eq. 29) is
// returned and is carried as a debt by the heavier sample.
// Energy compensation (eq. 30): a debt owed by a sample of group mass M = w m is given back at a
// later rebound of a sample s with 1/2 < w_s m_s / M < 2, by scaling the relative velocity of the
// rebounding pair in its centre-of-mass frame (momentum exact, energy increased by the debt).
#include <cstddef>

#include "agglo/acoustics/samples.hpp"
#include "agglo/core/vec3.hpp"

namespace agglo::acoustics {

// Merged properties of one real i and one real j (eqs. 15-17). Caches of i/j are not touched.
struct Merged {
  double vol_s, vol_l, mass;
  Vec3 v;
  int pop;
  Primaries primaries;  // n_p, r_p of the merged particle (structured runs only; else 0)
  double charge = 0.0;  // q_i + q_j [C] (samples carrying charge only; else 0)
};
Merged merged_state(const SampleSet& p, std::size_t i, std::size_t j);

// Weighted coalescence (eqs. 18-21). Refreshes the caches of the samples that changed.
void coalesce_weighted(SampleSet& p, std::size_t i, std::size_t j, const Gas& gas, const Sound& sound);

// Weighted rebound with normal n (unit, from i to j, (v_i - v_j).n > 0), restitution e and
// friction f. Returns the kinetic energy lost by the split-merge (eq. 29, >= 0; 0 for equal weights)
// and books it as a debt on the split sample.
double rebound_weighted(SampleSet& p, std::size_t i, std::size_t j, const Vec3& n, double e, double f);

// Adds energy dE [J] to the relative motion of samples s, t (group masses w m), momentum exact.
// Returns false (nothing changed) if the pair has no relative velocity.
bool add_relative_energy(SampleSet& p, std::size_t s, std::size_t t, double dE);

// Total kinetic energy sum_i w_i m_i |v_i|^2 / 2 [J] and momentum sum_i w_i m_i v_i.
double kinetic_energy(const SampleSet& p);
Vec3 momentum(const SampleSet& p);

}  // namespace agglo::acoustics
