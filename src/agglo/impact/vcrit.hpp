#pragma once
// Critical break-up velocity (MODEL.md A.3): the lowest speed from which on every tested speed
// breaks the agglomerate. A coarse scan over [v_min, v_max] runs in parallel; the transition above
// the highest non-breaking speed is then narrowed with several speeds per round (one per thread)
// to the tolerance. Non-monotonic outcomes (a break below a non-break) are reported, not hidden.
#include <functional>
#include <string>
#include <vector>

#include "agglo/impact/experiment.hpp"

namespace agglo::impact {

struct VcritResult {
  double v_crit = 0.0;           // = bracket hi: lowest speed with all higher tested speeds breaking
  double lo = 0.0, hi = 0.0;     // bracket [m/s]
  std::vector<ImpactOutcome> runs;  // every run, sorted by speed
  std::vector<std::string> warnings;   // non-monotonic or undecided outcomes
  int rounds = 0;
};

using RunFunction = std::function<ImpactOutcome(double)>;

// `run` is called concurrently from several threads (it must be thread-safe).
VcritResult find_vcrit(const VcritSpec& spec, int parallel_runs, const RunFunction& run,
                       const std::function<void(double)>& progress = {});

}  // namespace agglo::impact
