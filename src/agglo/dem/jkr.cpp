#include "agglo/dem/jkr.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::dem {

const double kJkrCbrt6 = std::cbrt(6.0);
const double kJkrSMin = 1.0 / std::cbrt(6.0);

JkrPair JkrPair::make(double R, double Estar, double gamma) {
  JkrPair p;
  p.R = R;
  p.Estar = Estar;
  p.gamma = gamma;
  p.Fc = 3.0 * constants::pi * gamma * R;
  p.a0 = std::cbrt(9.0 * constants::pi * gamma * R * R / Estar);
  p.deltaC = p.a0 * p.a0 / (2.0 * kJkrCbrt6 * R);
  return p;
}

double JkrPair::delta_of_a(double a) const {
  return a * a / R - 2.0 * std::sqrt(constants::pi * gamma * a / Estar);
}

}  // namespace agglo::dem
