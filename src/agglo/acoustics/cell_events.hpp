#pragma once
// Outcome of one accepted collision of two samples of a cell (docs/model.md §C.5), shared by the
// selection algorithms: coalescence (always for pairs with a droplet, or outcomes.always_coalesce)
// or, for solid/mixed pairs, rebound when the normal impact speed exceeds the critical velocity; with
// the dry (solid-solid) or wet (solid-mixed, mixed-mixed) outcome table, stick, bounce or break
// (fragments.hpp) drawn by that table's probabilities (one draw for both: table_outcome).
// The contact normal of a rebound is drawn for a hard-sphere encounter (uniform impact parameter
// over the collision disk). Samples whose weight drops to 0 are refilled by splitting the heaviest
// sample of the cell (decision), and split-merge energy debts are given back at later rebounds
// (Zhao et al. 2023, eq. 30). Every sample whose state changed is listed in touched() until clear_touched().
#include <cstdint>
#include <vector>

#include "agglo/acoustics/collision_step.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/core/rng.hpp"

namespace agglo::acoustics {

enum class CollisionOutcome { stick, bounce, brk };

class CellEvents {
 public:
  CellEvents(SampleSet& p, const std::uint32_t* idx, std::size_t n, const CollisionContext& ctx, CollisionStats& st,
             CounterRng& rng);
  // Collision of samples i and j (both live, i != j).
  void collide(std::size_t i, std::size_t j);
  const std::vector<std::uint32_t>& touched() const { return touched_; }
  void clear_touched() { touched_.clear(); }

 private:
  void list_debtors();
  void refill(std::size_t dead);
  void compensate(std::size_t i, std::size_t j);
  CollisionOutcome dry_outcome(std::size_t i, std::size_t j, double gn);
  CollisionOutcome wet_outcome(std::size_t i, std::size_t j, double gn);
  // The counters of one table (CollisionStats: the dry or the wet table's).
  struct TableTally {
    std::uint64_t &queries, &clamped, &turned_back;
  };
  // Pair (i, j) at normal speed gn drawn from table t with one uniform u: sticks if u < P_stick, breaks if
  // u < P_stick + P_break, else bounces (after the Coulomb launch conversion of a charged table with a gap).
  CollisionOutcome table_outcome(const OutcomeTable& t, TableTally c, std::size_t i, std::size_t j, double gn);
  // Table t's query of pair (i, j) at normal speed gn: volume-equivalent diameters, surface charge densities
  // q / (pi d_v^2) (samples carrying charge), mean kappa_p of the two populations, primary radii (t has them).
  OutcomeQuery table_query(const OutcomeTable& t, std::size_t i, std::size_t j, double gn) const;

  // A charged table with a launch gap (coulomb_launch.hpp): the speed of the last table outcome's query, and
  // whether the pair of this collision was turned back before the launch separation (a bounce without contact).
  double table_speed_ = 0.0;
  bool turned_back_ = false;
  SampleSet& p;
  const std::uint32_t* idx;
  const std::size_t n;
  const CollisionContext& ctx;
  CollisionStats& st;
  CounterRng& rng;
  const OutcomeParams& oc;
  std::vector<std::uint32_t> debtors, touched_;
  bool debtors_listed_ = false;  // debtors holds the start-of-step debtors (listed at the first collision)
};

}  // namespace agglo::acoustics
