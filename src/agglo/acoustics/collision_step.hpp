#pragma once
// What the collision step of one cell needs and what it reports, whichever selection algorithm
// picks the colliding pairs (time.selection: nanbu.hpp, Zhao et al.'s method; binned.hpp).
// Both realise the same pair rate (decision, see docs/acoustics.md): a collision event of samples
// i and j consumes min(w_i, w_j) real pairs (weighted rules, merge.hpp, fragments.hpp), and events of an unordered
// pair happen at rate beta_ij max(w_i, w_j) / V_c, so real collisions happen at beta_ij w_i w_j / V_c.
#include <cmath>
#include <cstdint>

#include "agglo/acoustics/drag.hpp"
#include "agglo/acoustics/kernels.hpp"
#include "agglo/acoustics/outcomes.hpp"
#include "agglo/acoustics/samples.hpp"

namespace agglo::acoustics {

enum class Selection { nanbu, binned };

struct CollisionStats {
  std::uint64_t trials = 0;          // Nanbu draws, or binned candidate pairs
  std::uint64_t kernel_evals = 0;    // draws that needed beta (not rejected by the majorant)
  std::uint64_t collisions = 0;
  std::uint64_t coalescences[3] = {0, 0, 0};  // by PairType: droplet, dry, wet
  std::uint64_t rebounds[3] = {0, 0, 0};
  std::uint64_t breakups[3] = {0, 0, 0};      // broke into fragments (pairs drawn from a table: fragments.hpp)
  std::uint64_t particle_steps = 0;  // (sample, step) pairs processed
  std::uint64_t subcycled = 0;       // Nanbu: particle steps that needed more than one trial interval;
                                     // binned: cell steps split into sub-steps
  std::uint64_t max_subcycles = 0;   // Nanbu: most trial intervals of one sample in one step; binned: sub-steps
  double max_bound_pn = 0.0;         // Nanbu: largest N * P_bound(dt_c) seen (> 1 means the guard acted)
  double max_pn = 0.0;               // Nanbu: largest N * P_ij evaluated; binned: largest rate / majorant (<= 1)
  std::uint64_t violations = 0;      // Nanbu: P_ij > 1/N; binned: rate > majorant (must stay 0)
  std::uint64_t refills = 0;         // zero-weight samples refilled by splitting
  std::uint64_t dead = 0;            // zero-weight samples that could not be refilled
  double energy_lost = 0.0;          // split-merge losses (eq. 29) [J]
  double energy_returned = 0.0;      // compensation given back (eq. 30) [J]
  std::uint64_t row_rate_updates = 0;  // binned: full computations of a row of group-pair rates
  std::uint64_t table_queries = 0;     // dry outcome table (outcomes.dry_model = "table"): queries
  std::uint64_t table_clamped = 0;     // of which outside the table on some axis (clamped to its end)
  std::uint64_t table_turned_back = 0; // charged table with a launch gap: pairs turned back by the Coulomb work
  std::uint64_t wet_table_queries = 0;      // the same three of the wet outcome table (outcomes.wet_model = "table")
  std::uint64_t wet_table_clamped = 0;
  std::uint64_t wet_table_turned_back = 0;
  void add(const CollisionStats& o);
};

struct CollisionContext {
  const Kernel* kernel = nullptr;
  const OutcomeParams* outcomes = nullptr;
  const Gas* gas = nullptr;
  const Sound* sound = nullptr;
  Domain domain;
  double dt = 0.0;                 // collision step dt_c [s]
  std::uint64_t seed = 0;
  bool strict = false;             // Nanbu guard = "strict": throw instead of sub-cycling
  std::uint64_t max_subcycles = 100000;
};

// Number of a in [begin, end) with v[idx[a]] > 0 (live samples by weight, debtors by debt): an integer
// sum, so it runs in SIMD lanes (AVX2 gathers where the processor has them, with GCC on x86-64).
std::size_t count_positive(const double* v, const std::uint32_t* idx, std::size_t begin, std::size_t end);

// std::nearbyint(q) in the default rounding mode (ties to even) without a call into libm: for |q| < 2^51,
// q + 1.5 2^52 lies in [2^52, 2^53), where doubles are the integers, so the addition rounds q to the
// nearest integer as nearbyint does and the subtraction is exact. (One difference: -0.3 gives +0, not -0;
// d - L n is then the same number, d.) Larger |q| and NaN take std::nearbyint.
inline double nearest_integer(double q) {
  if (!(std::abs(q) < 0x1p51)) return std::nearbyint(q);
  return (q + 0x1.8p52) - 0x1.8p52;
}

// Centre distance of samples i and j under the minimum-image convention of the periodic box [m].
inline double pair_distance(const SampleSet& p, std::size_t i, std::size_t j, const Domain& D) {
  const auto image = [](double d, double L) { return d - L * nearest_integer(d / L); };
  const double dx = image(p.x[i] - p.x[j], D.L[0]), dy = image(p.y[i] - p.y[j], D.L[1]);
  const double dz = image(p.z[i] - p.z[j], D.L[2]);
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

}  // namespace agglo::acoustics
