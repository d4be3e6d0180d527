#pragma once
// Modified Nanbu collision step of one cell (docs/model.md §C.4; Zhao et al. 2023, eqs. 6, 12; Tsuji et al. 1998).
// For each sample i of a cell with N live samples: R uniform in [0,1), candidate j = int(R N),
// collide iff R > (j+1)/N - P_ij. This gives probability exactly P_ij per partner only while
// P_ij <= 1/N.
// Pair probability (decision, see docs/acoustics.md): both samples of a pair are updated by the
// weighted rules (eqs. 18-28), which consume min(w_i, w_j) real pairs per event, and the pair is
// tested from both sides, so
//     P_ij = beta_ij max(w_i, w_j) dt_c / (2 V_c)
// makes the expected rate of real collisions beta_ij w_i w_j / V_c (Zhao et al.'s literal
// beta w_j dt/V_c counts equal-weight pairs twice).
// Guard: before each trial, a majorant B_i >= beta_ij over the cell (CellBounds) gives
// P_ij <= B_i w_max h / (2 V_c); the trial interval h of sample i is sub-cycled (h = dt_c / n_i)
// so that this bound is <= 1/N. The bound also gives a cheap rejection: if (j+1)/N - R is above
// it, beta need not be evaluated. Statistics of the guard are collected in CollisionStats.
// Samples whose weight drops to 0 (eq. 19 with w = 1) are refilled by splitting the heaviest
// sample of the cell (decision), so the sample count stays constant while possible.
#include <cstdint>
#include <vector>

#include "agglo/acoustics/collision_step.hpp"
#include "agglo/acoustics/samples.hpp"

namespace agglo::acoustics {

// Processes the samples listed in idx (all in one cell) for one collision step.
void collide_cell(SampleSet& p, const std::uint32_t* idx, std::size_t n, std::uint64_t cell, std::uint64_t step,
                  const CollisionContext& ctx, CollisionStats& st);

// Cell bounds of the listed samples (used by collide_cell and by the start-up guard check); with
// `live`, also the number of live samples (weight > 0) among them.
CellBounds cell_bounds(const SampleSet& p, const std::uint32_t* idx, std::size_t n, const Kernel& k,
                       const Gas& gas, std::size_t* live = nullptr);

// Number of trial intervals the guard needs for sample i (ceil(N P_bound)), given the bounds.
double guard_pn(const SampleSet& p, std::size_t i, std::size_t N, const CellBounds& cb, const Kernel& k,
                double dt, double cell_volume);

}  // namespace agglo::acoustics
