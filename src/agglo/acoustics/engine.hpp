#pragma once
// DSMC acoustic agglomeration engine (docs/model.md Part C): sampled particles in a periodic box,
// motion in the sound field (drag.hpp) over each collision step dt_c, then binning into cells
// and one collision step per cell by the selected algorithm (nanbu.hpp, binned.hpp). Cells run in parallel (OpenMP);
// every random draw comes from a counter-based stream keyed by (seed, cell, step) or
// (seed, population, sample), so a run is bitwise reproducible whatever the thread count.
// Storage order: a step's threads each take one contiguous block of cells, balanced by sample count, in
// both passes (motion and collisions; a thread done with its block helps with what is left of the others',
// block_claims.hpp). So that a block's samples are also contiguous in memory, runs of
// the Nanbu selection with kSortMinSamples or more samples store them sorted by cell (re-sorted every
// kResortEvery steps), while every result keeps the canonical order, the order the samples had without
// sorting: a cell's samples meet in canonical order, and particles() and the checkpoint restore it first.
#include <cstdint>
#include <string>
#include <vector>

#include "agglo/acoustics/drag.hpp"
#include "agglo/acoustics/kernels.hpp"
#include "agglo/acoustics/binned.hpp"
#include "agglo/acoustics/block_claims.hpp"
#include "agglo/acoustics/nanbu.hpp"
#include "agglo/acoustics/outcomes.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/acoustics/populations.hpp"
#include "agglo/acoustics/initial_placement.hpp"
#include "agglo/core/thread_choice.hpp"

namespace agglo::acoustics {

enum class InitialVelocity { steady, gas, rest };

struct EngineSettings {
  Motion motion;                      // gas, sound, domain, integrator
  KernelSettings kernel;
  OutcomeParams outcomes;
  std::vector<PopulationSpec> populations;
  SamplingSettings sampling;          // placement over the cells and cloning at t = 0 (initial_placement.hpp)
  double t_end = 4.0;                 // [s]
  double collision_dt = 1e-5;         // dt_c [s]
  double motion_dt = 1e-5;            // [s]; collision_dt / motion_dt substeps per collision step
  InitialVelocity initial_velocity = InitialVelocity::steady;
  Selection selection = Selection::nanbu;  // collision-pair selection (collision_step.hpp)
  bool strict_guard = false;
  std::uint64_t max_subcycles = 100000;
  std::uint64_t seed = 1;
  bool sort_storage = true;  // false: samples never stored sorted by cell (the reference twin of the sorted order)
};

class Engine {
 public:
  explicit Engine(EngineSettings s);

  // Advances one collision step (motion then collisions). Throws NumericalError on NaN or a
  // particle leaving the box.
  void step();
  double time() const { return static_cast<double>(step_) * s_.collision_dt; }
  std::uint64_t step_index() const { return step_; }
  std::uint64_t total_steps() const;
  int motion_substeps() const { return substeps_; }

  const EngineSettings& settings() const { return s_; }
  // The samples in canonical order (the storage order is restored first; the next step re-sorts).
  const SampleSet& particles() const {
    canonicalize();
    return p_;
  }
  SampleSet& particles() {
    canonicalize();
    blocks_fixed_ = false;  // the caller may move or add samples
    return p_;
  }
  // Times the samples were stored sorted by cell (the canonical order kept).
  std::uint64_t resorts() const { return resorts_; }
  const std::vector<SampledPopulation>& sampled() const { return sampled_; }
  const CollisionStats& stats() const { return stats_; }
  const Kernel& kernel() const { return kernel_; }
  // Thread counts the steps ran with (thread_choice.hpp: one thread where it was faster on this machine).
  const ThreadChoice& thread_choice() const { return threads_; }

  // Largest N * P_bound(dt_c) over the samples of the current state (guard check at start-up); the
  // sample attaining it in `argmax` when given.
  double max_guard_pn(std::size_t* argmax = nullptr) const;
  // Checks every sample for finite state and position inside the box.
  void check_state() const;
  // Recomputes caches and velocities after external edits (tests).
  void refresh_all();

 private:
  friend class EngineCheckpoint;  // saves and restores the state below (checkpoint.hpp)
  void bin();
  // The parts of step(), called inside its parallel region (engine.cpp).
  void move_pass(int thread, int team, bool& bad_state);  // motion, state check, cell index of the thread's block
  void sort_range(std::size_t q, int team, std::uint32_t* fill);  // the counting sort of rank range q (scatter)
  enum class Resort { none, keep_canonical, new_canonical };  // what reorder_by_cell does this step
  Resort resort_due(std::uint64_t step) const;               // (before the step's region: all threads agree)
  Resort prepare_step(bool move, int nt);  // shared state of the step's region, set before it
  void reorder_pass(int part, int parts, bool keep_canonical, int team);  // a part of reorder_by_cell
  void finish_reorder(bool keep_canonical, int team);  // its serial end (one thread, after the team's)
  // serial (thread 0): step counter, checks, the end of a re-sort, the blocks; `resorted`: the team ran
  // reorder_pass
  GroupReuse bin_step(bool moved, bool bad_state, Resort resort, bool resorted, int team);
  void collide_pass(const CollisionContext& ctx, GroupReuse reuse, std::vector<std::string>& errors, int thread,
                    int team);  // the cells of the thread's block
  // Storage order (engine.cpp): samples stored in the cell order of order_; keep_canonical: the canonical
  // order stays (rank_), else the new storage order becomes the canonical order (large sets, as before).
  void reorder_by_cell(bool keep_canonical);
  bool sorts_storage() const;
  void canonicalize() const;  // stored order back to canonical (cell_of_, order_ follow)
  void forget_storage_order() const;
  void fix_blocks();          // blocks of cells (and of stored samples) from the present sort
  void split_blocks();        // blocks of cells by the present counts, of samples evenly (unsorted storage)
  CollisionContext collision_context() const;
  void compute_cells(std::size_t begin, std::size_t end);  // cell_of_ for samples [begin, end)
  void sort_cells();  // order_, start_ from cell_of_, serial (the reference twin of move_pass + sort_range)
  bool state_ok(std::size_t begin, std::size_t end) const;  // fast test of check_state's conditions
  EngineSettings s_;
  mutable SampleSet p_;  // (mutable: the storage order, not the samples, changes in canonicalize())
  Kernel kernel_;
  std::vector<SampledPopulation> sampled_;
  CollisionStats stats_;
  std::uint64_t step_ = 0;
  int substeps_ = 1;
  mutable std::vector<std::uint32_t> cell_of_, order_;
  std::vector<std::uint32_t> start_, fill_;
  // By thread of a step's team: samples per rank range q (the team's sort_range ranges) and cell c at
  // [q * cells + c] (move_pass); and the sort's next slot per cell of the thread's range (sort_range).
  std::vector<std::vector<std::uint32_t>> thread_counts_, thread_fill_;
  std::vector<std::uint32_t> rank_next_, by_rank_next_, cell_next_;  // reorder_pass's results (finish_reorder)
  // With rank_: the first count of stored sample i's rank range for a team of range_team_ threads,
  // q(rank_[i]) * cells (set by reorder_pass; move_pass counts through it when its team is range_team_)
  std::vector<std::uint32_t> range_base_;
  mutable int range_team_ = 0;
  mutable std::vector<std::uint32_t> rank_, by_rank_;  // canonical position of stored sample i, and inverse
                                                       // (both empty: stored in canonical order)
  mutable bool blocks_fixed_ = false;  // blocks from a sort of the present storage
  std::vector<std::uint32_t> block_cells_, block_samples_;  // bounds of the blocks (cells; stored samples)
  std::uint64_t sorted_at_ = 0, resorts_ = 0;
  std::vector<BlockClaims> move_claims_, cell_claims_, sort_claims_, resort_claims_;  // the blocks' pieces and cells shared out (block_claims.hpp)
  std::vector<CollisionStats> cell_stats_;
  std::vector<std::uint32_t> local_of_;  // scratch of the binned selection
  std::vector<BinnedGroups> groups_;     // binned selection: groups of each cell
  bool regroup_ = true;                  // samples re-binned or reordered since the groups were built
  ThreadChoice threads_;                 // thread count of the parallel steps (wall time only)
};

}  // namespace agglo::acoustics
