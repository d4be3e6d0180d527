#pragma once
// Pivot grid of the fixed-pivot sectional method (Kumar & Ramkrishna 1996, Chem. Eng. Sci. 51:1311).
// Pivots are geometric in diameter: d_i = d_min 10^(i/b), i = 0..M-1 (b pivots per decade, the last
// one at or just above d_max), with volumes x_i = (pi/6) d_i^3 [m^3], so x_{i+1}/x_i = 10^(3/b).
// A particle of volume v with x_i <= v < x_{i+1} is shared by the two pivots around it,
//   a_i = (x_{i+1} - v) / (x_{i+1} - x_i),  a_{i+1} = 1 - a_i,
// the one split that keeps both its number (a_i + a_{i+1} = 1) and its volume (a_i x_i + a_{i+1} x_{i+1} = v).
// Below x_0 (at or above x_{M-1}) a particle goes whole to the first (last) pivot: number kept, volume not.
#include <cstddef>
#include <vector>

namespace agglo::sectional {

// Pivots `lo` and `hi` (hi = lo at the grid ends) receive the fractions a_lo and 1 - a_lo.
struct Split {
  std::size_t lo = 0, hi = 0;
  double a_lo = 1.0;
};

struct Grid {
  std::vector<double> d;  // pivot diameters [m]
  std::vector<double> x;  // pivot volumes [m^3]
  double ratio_d = 1.0;   // d_{i+1} / d_i

  // Throws std::invalid_argument unless 0 < d_min < d_max and bins_per_decade >= 1.
  static Grid geometric(double d_min, double d_max, int bins_per_decade);
  std::size_t size() const { return x.size(); }
  Split split(double v) const;
};

}  // namespace agglo::sectional
