#pragma once
// Binned majorant selection of the collision pairs of one cell (time.selection = "binned"; the binned
// method of PartMC, Riemer et al. 2009, Michelotti et al. 2013, extended to differential weights and
// to the acoustic kernel sum). Its cost follows the number of real collisions, not N x kernel range.
// The live samples of the cell are grouped by size class (kSizeClassesPerOctave per octave of diameter:
// binary exponent and first mantissa bit of d, class edges 1 and 1.5 times powers of 2) and weight class
// (binary exponent of w / 2: a factor 4 per class); the classes come from the bits of the doubles, no
// logarithm. Each group keeps upper bounds of what the kernels read (CellBounds: largest diameter, C_c/d,
// d l, volume, thermal speed, weight, speed about the group's mean velocity). For every pair of groups
// (a, b) and every kernel mechanism m (beta is a sum of non-negative mechanisms, bounded separately so
// that the 1/r terms bounded at contact do not sink the acceptance of the others) the majorant
//     M_m(a, b) = bound_pair_m(a, b) max(w_max,a, w_max,b)  >=  beta_m,ij max(w_i, w_j)
// gives candidate events at total rate n_pairs(a, b) sum_m M_m / V_c over the step dt_c, drawn as a
// Poisson process in time (exponential gaps). A candidate picks m with probability M_m / sum M, i
// uniform in a and j uniform in b (j != i), and collides with probability beta_m,ij max(w_i, w_j) / M_m.
// So unordered pairs collide at rate beta_ij max(w_i, w_j) / V_c, the Nanbu step's rate
// (collision_step.hpp). After every collision the changed samples move to their new groups, the
// groups' bounds take them in (bounds only grow within a step) and the rates of the row of group pairs
// being processed are updated (a Fenwick tree of the row's rates, rate_tree.hpp: O(log groups) per
// update and draw), so the majorant stays valid after rebounds and energy compensation; a candidate
// whose ratio exceeds 1 is counted in CollisionStats::violations (must stay 0). Groups persist between
// steps when the samples do not move (the engine's choice, GroupReuse), their bounds recomputed from the
// present members every kRetightenEvery steps. When the samples move, a cell's groups follow them: the
// members that left the cell are dropped, the samples that arrived join the group of their class, and the
// bounds are recomputed from the members (velocities change every step); the groups are then, as sets,
// those a rebuild would make (classes change only in collisions), in another order. Pairs of groups are processed
// one after the other (operator splitting, as PartMC's): a sample that changes group meets the groups
// after its new one for the whole interval, so the error grows with the fraction of samples that
// collide per interval (constant kernel, 1e5 samples: N(T) -2.8 % at 18 % per step). The step is
// therefore split into as many sub-steps as keep the previous step's collisions of the cell below
// kMaxCollisionFraction of its live samples per sub-step (first step: the expected candidates instead).
// Random draws come from a stream keyed by (seed, cell, step).
#include <cstdint>
#include <vector>

#include "agglo/acoustics/collision_step.hpp"
#include "agglo/acoustics/samples.hpp"

namespace agglo::acoustics {

inline constexpr int kSizeClassesPerOctave = 2;   // of diameter (first mantissa bit)
inline constexpr int kWeightOctavesPerClass = 2;  // a factor 4 of weight per class
inline constexpr std::uint64_t kRegroupEvery = 32;  // steps between rebuilds of the groups of a moving run
// Steps between recomputations of the bounds of kept groups (no motion). Without motion only collisions
// change a group, and a group's bounds can never exceed what its size and weight classes allow (a factor
// 2^(1/2) of diameter, 4 of weight), so former members loosen them little:
// PartMC's Brownian case, 5e4 samples, 1440 steps, recomputed every 32 steps against never: 243579
// against 244710 candidates (+0.5 %), for 17 % of the run's instructions (docs/acoustics.md §5.7).
// Kept as a safety net for bounds that can grow without limit (speeds after rebounds).
inline constexpr std::uint64_t kRetightenEvery = 1024;
inline constexpr double kMaxCollisionFraction = 0.02;  // collisions per live sample and sub-step (target)
inline constexpr std::uint64_t kMaxSubsteps = 1024;
inline constexpr std::uint64_t kMaxFirstSubsteps = 64;  // first step: from the expected candidates instead

struct BinnedGroup {
  std::vector<std::uint32_t> members;  // local positions in the cell's sample list
  std::vector<std::uint32_t> ids;      // the members' sample indices at the end of the last step (follow)
  CellBounds cb;                       // bounds over the members (and former members: they only grow)
  std::uint32_t key = 0;               // size and weight class
};

// The groups of one cell. They are kept from one step to the next while nothing but collisions changes
// the samples (no motion, same sample order): then a step costs the group pairs and the collisions, not N.
struct BinnedGroups {
  std::vector<BinnedGroup> groups;
  std::size_t count = 0;                           // groups[0, count) in use
  std::vector<double> size;                        // by group: number of members (read by every row)
  std::vector<std::uint64_t> version;              // by group: changes whenever cb may have changed
  std::vector<std::uint32_t> group_of, pos_of;     // by local position
  std::vector<std::uint8_t> grouped;               // by local position: 1 if in a group
  std::vector<std::uint64_t> slots;                // open addressing: (key + 1) << 32 | group, 0 = empty
  std::uint64_t last_collisions = 0;               // collisions of the cell's previous step (sub-step count)
  bool has_history = false;                        // last_collisions is known
  bool ids_valid = false;                          // groups[].ids hold the last step's members (follow)
  // Majorants of group pairs (a <= b at e = a * cache_cap + b: their sum over the mechanisms at cache_sum[e],
  // each mechanism's at cache_m[e * mechanisms + m]), valid while both groups keep the versions stored with
  // them. Versions come from one counter that never repeats.
  std::uint64_t clock = 0;
  std::size_t cache_cap = 0;
  std::vector<double> cache_sum, cache_m;
  std::vector<std::uint64_t> cache_va, cache_vb;
};

// How a step treats the groups of the previous step: rebuild them (a new sample order, and every
// kRegroupEvery steps of a moving run: empty groups are dropped), keep them (no motion), keep them with
// bounds recomputed from their present members (no motion, every kRetightenEvery steps: the bounds of
// samples that left a group would loosen it), or follow the moving samples (drop the members that left
// the cell, add the samples that arrived, bounds from the members).
enum class GroupReuse { rebuild, keep, retighten, follow };

// Processes the samples listed in idx (all in one cell) for one collision step. With keep or retighten,
// `groups` must hold this cell's groups of the previous step over the same list; with follow, the groups
// of the previous step whose ids were stored (cell_of given then); otherwise they are rebuilt. local_of
// is scratch indexed by sample (at least p.size() entries; a cell writes only its own samples' entries,
// and they must be left alone between steps that reuse the groups). cell_of: the cell of every sample this
// step (moving runs; nullptr without motion): with it the members' sample indices are stored at the end of
// the step for the next step's follow, and follow drops the members whose cell is no longer this one.
void binned_collide_cell(SampleSet& p, const std::uint32_t* idx, std::size_t n, std::uint64_t cell,
                         std::uint64_t step, const CollisionContext& ctx, CollisionStats& st, std::uint32_t* local_of,
                         BinnedGroups& groups, GroupReuse mode, const std::uint32_t* cell_of = nullptr);

}  // namespace agglo::acoustics
