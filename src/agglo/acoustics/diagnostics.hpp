#pragma once
// Diagnostics of a sampled state (docs/model.md §C.6):
//  - number concentrations by phase (sum of weights / box volume) [1/m^3];
//  - fine efficiency eta(t) = (N_f,0 - N_f(t)) / N_f,0 where N_f counts particles without liquid
//    (decision: "fine" = solid phase);
//  - fraction of droplets still pure = N_liquid(t) / N_liquid(0);
//  - dN/dlog10 d by phase on log-spaced bins [1/m^3];
//  - total solid and liquid volume per box volume (conservation checks) [m^3/m^3].
#include <array>
#include <vector>

#include "agglo/acoustics/samples.hpp"

namespace agglo::acoustics {

struct Counts {
  double n_total = 0.0;
  std::array<double, 3> n_phase{};      // by Phase: solid, liquid, mixed [1/m^3]
  double solid_volume = 0.0;            // sum w V_s / V
  double liquid_volume = 0.0;           // sum w V_l / V
  double mass = 0.0;                    // sum w m / V
  std::size_t live_samples = 0;
};
Counts count(const SampleSet& p, double box_volume);

struct PsdBins {
  std::vector<double> edges;  // diameters [m], size K+1, log spaced
  static PsdBins log_spaced(double dmin, double dmax, int k);
  int find(double d) const;   // -1 outside
};

// dN/dlog10 d for each phase (index by Phase) and all particles (index 3).
std::array<std::vector<double>, 4> psd(const SampleSet& p, double box_volume, const PsdBins& bins);

}  // namespace agglo::acoustics
