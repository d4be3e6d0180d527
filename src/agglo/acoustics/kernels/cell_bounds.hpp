#pragma once
// Aggregates of one cell from which every mechanism bounds its kernel over all pairs of the cell
// (majorant of the Nanbu guard, docs/model.md §C.4).
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "agglo/acoustics/gas.hpp"
#include "agglo/acoustics/samples.hpp"

namespace agglo::acoustics {

// What a mechanism needs beyond the per-sample caches: the centre distance r of a pair, the
// thermal speeds (CellBounds::cbar_max) or the particle volumes (CellBounds::vol_max).
struct KernelNeeds {
  bool distance = false;
  bool thermal_speed = false;
  bool volume = false;
};

struct CellBounds {
  double d_max = 0.0;        // largest diameter
  double vol_max = 0.0;      // largest particle volume
  double dl_max = 0.0;       // largest d l
  double ccd_max = 0.0;      // largest C_c / d
  double speed_dev_max = 0.0;// largest |v - v_ref| (valid after finalize())
  double speed_dev2_max = 0.0;// its square
  double w_max = 0.0;        // largest weight
  double cbar_max = 0.0;     // largest thermal speed (Fuchs), that of the lightest particle
  double mass_min = 0.0;     // lightest particle mass [kg] (tracked with cbar_max; 0 = none yet)
  double d_min = 0.0;        // smallest diameter (0 = none yet)
  double mass_max = 0.0;     // heaviest particle mass [kg]
  // Derived by Kernel::prepare from d_min, mass_max and cbar_max and nothing else of the bounds (the binned
  // selection skips prepare when an include left those three unchanged) (binned selection, transition-regime
  // Brownian bounds): largest Brownian diffusivity [m^2/s] and largest l = 8 D / (pi c) [m].
  double diff_max = 0.0, gap_max = 0.0;
  double vref[3] = {0, 0, 0};// reference velocity of the cell
  bool need_cbar = false;    // track cbar_max (Fuchs only)
  void include(const SampleSet& p, std::size_t i, const Gas& gas);
  // include(p, idx[members[k]], gas) for k = 0 .. n-1 in that order, bit for bit (the binned selection's
  // bounds of a whole group): one loop with the maxima in registers instead of a call per sample (both are
  // one function, cell_bounds.cpp).
  void include_all(const SampleSet& p, const std::uint32_t* idx, const std::uint32_t* members, std::size_t n,
                   const Gas& gas);
  void finalize() { speed_dev_max = std::sqrt(speed_dev2_max); }
};

}  // namespace agglo::acoustics
