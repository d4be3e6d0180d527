#pragma once
// DSMC acoustic agglomeration engine (docs/model.md Part C): sampled particles in a periodic box,
// motion in the sound field (drag.hpp) over each collision step dt_c, then binning into cells
// and one collision step per cell by the selected algorithm (nanbu.hpp, binned.hpp). Cells run in parallel (OpenMP);
// every random draw comes from a counter-based stream keyed by (seed, cell, step) or
// (seed, population, sample), so a run is bitwise reproducible whatever the thread count.
#include <cstdint>
#include <string>
#include <vector>

#include "agglo/acoustics/drag.hpp"
#include "agglo/acoustics/kernels.hpp"
#include "agglo/acoustics/binned.hpp"
#include "agglo/acoustics/nanbu.hpp"
#include "agglo/acoustics/outcomes.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/acoustics/populations.hpp"
#include "agglo/acoustics/initial_placement.hpp"
#include "agglo/acoustics/thread_choice.hpp"

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
  const SampleSet& particles() const { return p_; }
  SampleSet& particles() { return p_; }
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
  void move_pass(bool& bad_state);                // motion, state check, cell index (omp for)
  GroupReuse bin_step(bool moved, bool bad_state);  // serial: step counter, checks, sort by cell
  void collide_pass(const CollisionContext& ctx, GroupReuse reuse, std::vector<std::string>& errors);  // omp for
  CollisionContext collision_context() const;
  void compute_cells(std::size_t begin, std::size_t end);  // cell_of_ for samples [begin, end)
  void sort_cells();                                        // order_, start_ from cell_of_
  bool state_ok(std::size_t begin, std::size_t end) const;  // fast test of check_state's conditions
  EngineSettings s_;
  SampleSet p_;
  Kernel kernel_;
  std::vector<SampledPopulation> sampled_;
  CollisionStats stats_;
  std::uint64_t step_ = 0;
  int substeps_ = 1;
  std::vector<std::uint32_t> cell_of_, order_, start_, fill_;
  std::vector<CollisionStats> cell_stats_;
  std::vector<std::uint32_t> local_of_;  // scratch of the binned selection
  std::vector<BinnedGroups> groups_;     // binned selection: groups of each cell
  bool regroup_ = true;                  // samples re-binned or reordered since the groups were built
  ThreadChoice threads_;                 // thread count of the parallel steps (wall time only)
};

}  // namespace agglo::acoustics
