#pragma once
// Modified Nanbu collision step of one cell (docs/model.md §C.4; seed eqs. 6, 12; Tsuji et al. 1998).
// For each sample i of a cell with N live samples: R uniform in [0,1), candidate j = int(R N),
// collide iff R > (j+1)/N - P_ij. This gives probability exactly P_ij per partner only while
// P_ij <= 1/N.
// Pair probability (decision, see docs/acoustics.md): both samples of a pair are updated by the
// weighted rules (eqs. 18-28), which consume min(w_i, w_j) real pairs per event, and the pair is
// tested from both sides, so
//     P_ij = beta_ij max(w_i, w_j) dt_c / (2 V_c)
// makes the expected rate of real collisions beta_ij w_i w_j / V_c (the seed's literal
// beta w_j dt/V_c counts equal-weight pairs twice).
// Guard: before each trial, a majorant B_i >= beta_ij over the cell (CellBounds) gives
// P_ij <= B_i w_max h / (2 V_c); the trial interval h of sample i is sub-cycled (h = dt_c / n_i)
// so that this bound is <= 1/N. The bound also gives a cheap rejection: if (j+1)/N - R is above
// it, beta need not be evaluated. Statistics of the guard are collected in NanbuStats.
// Samples whose weight drops to 0 (eq. 19 with w = 1) are refilled by splitting the heaviest
// sample of the cell (decision), so the sample count stays constant while possible.
#include <cstdint>
#include <vector>

#include "agglo/acoustics/drag.hpp"
#include "agglo/acoustics/kernels.hpp"
#include "agglo/acoustics/outcomes.hpp"
#include "agglo/acoustics/samples.hpp"

namespace agglo::acoustics {

struct NanbuStats {
  std::uint64_t trials = 0;          // Nanbu draws
  std::uint64_t kernel_evals = 0;    // draws that needed beta (not rejected by the majorant)
  std::uint64_t collisions = 0;
  std::uint64_t coalescences[3] = {0, 0, 0};  // by PairType: droplet, dry, wet
  std::uint64_t rebounds[3] = {0, 0, 0};
  std::uint64_t particle_steps = 0;  // (sample, step) pairs processed
  std::uint64_t subcycled = 0;       // of those, how many needed more than one trial interval
  std::uint64_t max_subcycles = 0;   // largest number of trial intervals of one sample in one step
  double max_bound_pn = 0.0;         // largest N * P_bound(dt_c) seen (> 1 means the guard acted)
  double max_pn = 0.0;               // largest N * P_ij actually evaluated (must stay <= 1)
  std::uint64_t violations = 0;      // evaluated P_ij > 1/N (must stay 0)
  std::uint64_t refills = 0;         // zero-weight samples refilled by splitting
  std::uint64_t dead = 0;            // zero-weight samples that could not be refilled
  double energy_lost = 0.0;          // split-merge losses (eq. 29) [J]
  double energy_returned = 0.0;      // compensation given back (eq. 30) [J]
  void add(const NanbuStats& o);
};

struct CollisionContext {
  const Kernel* kernel = nullptr;
  const OutcomeParams* outcomes = nullptr;
  const Gas* gas = nullptr;
  const Sound* sound = nullptr;
  Domain domain;
  double dt = 0.0;                 // collision step dt_c [s]
  std::uint64_t seed = 0;
  bool strict = false;             // guard = "strict": throw instead of sub-cycling
  std::uint64_t max_subcycles = 100000;
};

// Processes the samples listed in idx (all in one cell) for one collision step.
void collide_cell(SampleSet& p, const std::uint32_t* idx, std::size_t n, std::uint64_t cell, std::uint64_t step,
                  const CollisionContext& ctx, NanbuStats& st);

// Cell bounds of the listed samples (used by collide_cell and by the start-up guard check).
CellBounds cell_bounds(const SampleSet& p, const std::uint32_t* idx, std::size_t n, const Kernel& k,
                       const Gas& gas);

// Number of trial intervals the guard needs for sample i (ceil(N P_bound)), given the bounds.
double guard_pn(const SampleSet& p, std::size_t i, std::size_t N, const CellBounds& cb, const Kernel& k,
                double dt, double cell_volume);

}  // namespace agglo::acoustics
