#pragma once
// Critical break-up velocity (docs/model.md §A.3): the lowest speed from which on every tested speed
// breaks the agglomerate. A coarse scan over [v_min, v_max] (scan_points speeds) is followed by
// bisection rounds that each try `points_per_round` evenly spaced speeds inside the bracket above the
// highest non-breaking speed, until the bracket is narrower than the tolerance. The speeds tried
// depend only on the configuration and the outcomes, never on the number of cores. Non-monotonic
// outcomes (a break below a non-break) are reported, not hidden.
// vcrit.criterion = "sticking" bisects the same way on "does not stay" instead of "breaks" (stays():
// the agglomerate on the wall with wall.impact, else the projectile on the target) and reports the
// largest speed that stays, v_crit = the bracket's lower end.
// vcrit.order = "top_down" runs each batch (the scan, every round) from its highest speed down and stops
// at the first speed without the event: the bracket only needs the highest such speed, so v_crit, the
// bracket, the rounds and every run at or above the bracket's lower end are those of the full order; the
// runs below it (and the warnings they would raise) are skipped.
#include <functional>
#include <string>
#include <vector>

#include "agglo/impact/experiment.hpp"

namespace agglo::impact {

struct VcritResult {
  bool sticking = false;         // the criterion (VcritSpec::sticking)
  double v_crit = 0.0;           // breakup: bracket hi, lowest speed with all higher tested speeds breaking;
                                 // sticking: bracket lo, highest speed that stays below all rebounds
  double lo = 0.0, hi = 0.0;     // bracket [m/s]
  std::vector<ImpactOutcome> runs;  // every run, sorted by speed
  std::vector<std::string> warnings;   // non-monotonic or undecided outcomes
  int rounds = 0;
};

// Says whether the speeds after this outcome in a batch are still needed (true: they are not).
using StopRule = std::function<bool(const ImpactOutcome&)>;

// Runs a batch of independent impacts at the given speeds and returns their outcomes in the same
// order (e.g. run::speed_batch: in parallel, journaled). With a `stop` rule the speeds are taken in the
// order given and the batch returns the outcomes up to and including the first one the rule accepts
// (all when none does); the later speeds need not run (the result never depends on whether they did).
using SpeedBatch = std::function<std::vector<ImpactOutcome>(const std::vector<double>& speeds, const StopRule& stop)>;

// The impact stayed: with a wall impact no fragment rebounded (Breakage::wall, breakage.hpp); else the
// projectile (its particle of highest index) is in contact with the agglomerate (some of its first
// n_agg particles, n_agg = the primaries of all fragments) at the end. False without contact.
bool stays(const ImpactOutcome& o);

VcritResult find_vcrit(const VcritSpec& spec, const SpeedBatch& run_batch,
                       const std::function<void(double)>& progress = {});

}  // namespace agglo::impact
