#include "agglo/acoustics/coulomb_launch.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

double coulomb_launch_speed(double vn, double qi, double qj, double mi, double mj, double di, double dj, double gap,
                            double kappa0) {
  const double ri = 0.5 * di, rj = 0.5 * dj;
  const double s = ri + rj + gap * std::min(ri, rj);
  const double u = qi * qj / (4.0 * constants::pi * constants::eps0 * kappa0 * s);
  const double mu = mi * mj / (mi + mj);
  const double v2 = vn * vn - 2.0 * u / mu;
  return v2 < 0.0 ? -1.0 : std::sqrt(v2);
}

}  // namespace agglo::acoustics
