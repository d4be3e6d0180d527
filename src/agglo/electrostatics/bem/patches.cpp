#include "agglo/electrostatics/bem/patches.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::es::bem {

std::vector<Vec3> fibonacci_sphere(int n) {
  std::vector<Vec3> u(n > 0 ? n : 0);
  const double ga = constants::pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / n;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    u[k] = {rho * std::cos(ga * k), rho * std::sin(ga * k), z};
  }
  return u;
}

}  // namespace agglo::es::bem
