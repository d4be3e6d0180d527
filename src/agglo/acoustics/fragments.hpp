#pragma once
// Weighted breakage of a colliding pair into fragments (docs/model.md §C.5, docs/acoustics.md §1.7): the
// outcome "break" of the dry outcome table (outcome_table.hpp) with its fragment statistics at the pair's
// normal speed and diameters: mean fragment number N_f >= 2 and mass fraction of the largest f_L.
// Fragment model (decision): a broken pair of mass M = m_i + m_j gives one fragment of f_L M and
// N_f - 1 fragments of (1 - f_L) M / (N_f - 1) each, all at the pair's centre-of-mass velocity
//   v_cm = (m_i v_i + m_j v_j) / M,
// with the pair's solid and liquid volumes in proportion to mass (density kept) and the population of
// the partner of larger volume (as coalescence, merge.hpp).
// Weighted rule (decision): the event breaks W = min(w_i, w_j) real pairs, the number a collision event
// of samples i, j consumes (collision_step.hpp). No sample is created: the two samples of the pair take
// the fragments by their weights, so the sample count stays what it was. R(x) = floor(x) + [u < x - floor(x)]
// (u uniform in [0, 1)) rounds a weight stochastically to an integer with E[R(x)] = x (R(x) = x when W
// is not a whole number, which the samplers never make; for whole W every R(x) below is >= W >= 1).
//   w_i = w_j = W:  i <- the largest fragments: weight W, mass f_L M;
//                   j <- the others: weight c = R(W (N_f - 1)), mass W (1 - f_L) M / c.
//   w_h > w_l = W:  h keeps its state with weight w_h - W;
//                   l <- one class, drawn in proportion to its mass share: the largest with probability
//                   f_L (weight c = R(W / f_L)), else the others (c = R(W (N_f - 1) / (1 - f_L)));
//                   mass W M / c each.
// Conservation: the fragment samples hold weight x mass = W M in both cases (c cancels), and all move at
// v_cm, so mass and momentum W M v_cm = W (m_i v_i + m_j v_j) are those of the W pairs, exactly up to
// rounding, as in coalescence. The number of real particles goes from 2 W to W N_f in expectation:
// W + E[R(W (N_f - 1))] = W N_f, and f_L W / f_L + (1 - f_L) W (N_f - 1) / (1 - f_L) = W N_f; per event
// it is an integer (weights stay integer-valued): within one of W N_f for equal weights, the rounded
// count of the drawn class (W / f_L or W (N_f - 1) / (1 - f_L)) for unequal ones. The mass carried by each class is
// right per event (equal weights) or in expectation (unequal: f_L of W M in the largest class); per event
// the fragment mass of an unequal-weight break deviates from f_L M (or the others' mass) by the rounding
// of c, at most a factor (c + 1) / c. Kinetic energy of the relative motion is lost, as in coalescence.
// Split-merge debts (merge.hpp) follow coalescence: equal weights pool them on i, else they stay.
// With a fragment mass distribution (outcome_table.hpp: per bin b the mean number h_b and mass fraction
// mu_b of the fragments of one broken pair; FragmentStats::bins > 0), the classes are its bins (decision):
// a sample that takes the fragments of bin b and holds weight x mass = X becomes
//   c = R(X h_b / (mu_b M)) fragments (at least 1) of mass X / c each,
// the bin drawn in proportion to mu_b (the mass share).
//   w_i = w_j = W:  i and j each hold X = W M / 2, their bins drawn with the uniforms u and u + 1/2 (mod 1)
//                   (each uniform: the expectations below; together: the two halves rarely the same bin);
//   w_h > w_l = W:  h keeps its state with weight w_h - W; l holds X = W M in one drawn bin.
// Expected mass in bin b: sum over the holders of P(b) X = mu_b W M, so the expected number in bin b is
// mu_b W M h_b / (mu_b M) = W h_b, and W N_f in all; the fragments' mean mass in bin b is mu_b M / h_b.
// Mass and momentum are exact per event as above (each holder keeps X at v_cm). The floor c >= 1 matters
// only when X < mu_b M / h_b, i.e. equal weights W = 1 and a bin whose mean fragment exceeds M / 2 (the
// fragment is then lighter than the bin's mean and the count above its expectation): a bias of that case.
// Draws 3 (equal weights) or 2 uniforms.
// Aggregate structure (structure.hpp): a fragment of mass f M holds f (n_i + n_j) primaries of the pair's
// (merged) primary radius, so primary count and solid volume are conserved as the mass is.
#include <cstddef>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/core/rng.hpp"

namespace agglo::acoustics {

// Breaks the W = min(w_i, w_j) real pairs of samples i, j (both live) by the rule above and refreshes the
// caches of the samples that changed. Draws 1 (equal weights) or 2 uniforms from `rng` (with a
// distribution, f.bins > 0: 3 or 2).
void break_weighted(SampleSet& p, std::size_t i, std::size_t j, const FragmentStats& f, CounterRng& rng,
                    const Gas& gas, const Sound& sound);

}  // namespace agglo::acoustics
