#include "agglo/acoustics/structure.hpp"

#include <algorithm>
#include <cmath>

namespace agglo::acoustics {

double collision_radius(const StructureLaw& law, double n, double rp, double rv) {
  if (!law.fractal) return rv;
  return std::max(rv, rp * std::pow(n / law.fractal_prefactor, 1.0 / law.fractal_dimension));
}

double mobility_radius(const StructureLaw& law, double n, double rp, double rv) {
  if (!law.fractal) return rv;
  if (law.mobility == MobilityRule::collision) return collision_radius(law, n, rp, rv);
  return std::max(rv, rp * std::pow(n, kSorensenMobilityExponent));
}

Primaries merged_primaries(double ni, double ri, double nj, double rj) {
  if (!(nj > 0.0)) return {ni, ri};
  if (!(ni > 0.0)) return {nj, rj};
  const double n = ni + nj;
  if (ri == rj) return {n, ri};
  return {n, std::cbrt((ni * ri * ri * ri + nj * rj * rj * rj) / n)};
}

}  // namespace agglo::acoustics
