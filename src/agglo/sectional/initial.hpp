#pragma once
// Initial state of the sectional solver: each [[population]] of the case projected onto the pivots
// (grid.hpp) so that number and volume are kept exactly. The particles with volume in [x_i, x_{i+1})
// (number n, volume V in 1/m^3 and m^3/m^3) go to pivot i+1 as (V - x_i n)/(x_{i+1} - x_i) and to pivot i
// as the rest: the split of grid.hpp integrated over the interval. Closed-form partial moments:
//   lognormal in d (d_g, s = ln sigma_g; the whole distribution, not the 3.5 sigma cut of the DSMC sampler):
//     n = N [Phi(z_b) - Phi(z_a)],  V = N (pi/6) d_g^3 e^(9 s^2/2) [Phi(z_b - 3s) - Phi(z_a - 3s)],
//     z = ln(d / d_g) / s,
//   exponential in volume (n(v) = N/v0 e^(-v/v0)): n = N [e^(-a/v0) - e^(-b/v0)],
//     V = N [(a + v0) e^(-a/v0) - (b + v0) e^(-b/v0)],
//   monodisperse and table: points of known volume.
// Particles below the first pivot (above the last) go whole to it; their share is reported.
#include <vector>

#include "agglo/acoustics/populations.hpp"
#include "agglo/sectional/grid.hpp"

namespace agglo::sectional {

// Number [1/m^3] and volume [m^3/m^3] of the particles with volume in [a, b) [m^3] (b may be +inf).
struct Moments {
  double number = 0.0, volume = 0.0;
};
Moments population_moments(const acoustics::PopulationSpec& p, double a, double b);

struct Projection {
  std::vector<double> n;          // number concentration of each pivot [1/m^3]
  Moments below, above;           // particles smaller than the first / larger than the last pivot
};
Projection project(const Grid& g, const std::vector<acoustics::PopulationSpec>& pops);

}  // namespace agglo::sectional
