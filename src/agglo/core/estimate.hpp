#pragma once
// Cost estimate ("estimate" in agglo always means the cost of a run, never a physical estimate): what a
// run will cost, estimated from the validated case before anything large is allocated (docs/limits.md).
// Three quantities, each with the config keys that drive it:
//   steps   particle-steps: time steps x particles, summed over every run a command makes (DEM);
//           collision steps x samples x (1 + motion sub-steps) (DSMC); spheres (a static solve)
//   memory  peak resident bytes of the process (the arrays the engine and the recorders allocate)
//   output  bytes written into the output folder
// Engines provide upper bounds or close estimates (impact/estimate.hpp, acoustics/estimate.hpp,
// electrostatics/estimate.hpp); run::execute compares them with the budgets (run/budget.hpp).
#include <string>
#include <vector>

namespace agglo {

struct EstimateItem {
  double value = 0.0;              // steps or bytes (a double: a typo may ask for 1e300)
  std::vector<std::string> keys;   // dotted config keys that drive it, most important first
};

struct Estimate {
  EstimateItem steps, memory, output;
};

// Adds `v` to `item` and appends the keys it does not list yet.
inline void add_to(EstimateItem& item, double v, const std::vector<std::string>& keys) {
  item.value += v;
  for (const auto& k : keys) {
    bool known = false;
    for (const auto& have : item.keys) known = known || have == k;
    if (!known) item.keys.push_back(k);
  }
}

}  // namespace agglo
