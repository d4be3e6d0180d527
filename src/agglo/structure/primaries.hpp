#pragma once
// Primary radii of the generated aggregates (docs/model.md §S.1): monodisperse (sigma_g = 1) or
// lognormal, ln a ~ Normal(ln a_g, ln sigma_g), truncated at +-3 ln sigma_g (redrawn outside; the
// truncation removes 0.27 % of the distribution). a_g [m] is the geometric mean (median), sigma_g >= 1
// the geometric standard deviation. The fractal law uses the geometric mean of the drawn radii,
// abar = exp(<ln a_i>) over all N primaries of the aggregate (geometric_mean below).
#include <vector>

#include "agglo/core/rng.hpp"

namespace agglo::structure {

std::vector<double> primary_radii(int n, double a_g, double sigma_g, CounterRng& rng);
// exp(mean of ln r) [m]
double geometric_mean(const std::vector<double>& r);

}  // namespace agglo::structure
