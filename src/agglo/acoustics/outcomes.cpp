#include "agglo/acoustics/outcomes.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

double critical_velocity_dry(const OutcomeParams& o, double di, double dj, double rhoi, double rhoj) {
  const double dmin = std::min(di, dj), dmax = std::max(di, dj);
  const double rhomin = di <= dj ? rhoi : rhoj;
  const double e = o.restitution;
  return o.hamaker * std::sqrt(1.0 - e * e) /
         (constants::pi * dmin * o.z0 * o.z0 * e * e *
          std::sqrt(6.0 * o.contact_pressure * rhomin * (1.0 + dmin / dmax)));
}

double critical_velocity_wet(const OutcomeParams& o, double di, double dj) {
  const double e = o.restitution;
  return 9.0 * o.liquid_viscosity * (di + dj) / (8.0 * o.solid_density * di * dj) * (1.0 + 1.0 / e) *
         std::log(o.film_ratio);
}

double wet_restitution(const OutcomeParams& o, double di, double dj, double gn) {
  const double e = o.restitution;
  const double ew = e - 9.0 * o.liquid_viscosity * (di + dj) * (1.0 + e) * std::log(o.film_ratio) /
                            (8.0 * o.solid_density * di * dj * std::abs(gn));
  return std::max(ew, 0.0);
}

void hard_sphere_rebound(const Vec3& vi, const Vec3& vj, double mi, double mj, const Vec3& n, double e, double f,
                         Vec3& vi_out, Vec3& vj_out) {
  const Vec3 G = vi - vj;
  const double gn = dot(n, G);
  const Vec3 Gt = G - gn * n;
  const double gt = norm(Gt);
  const double fi = mj / (mi + mj), fj = mi / (mi + mj);
  Vec3 J;  // change of relative velocity direction times magnitude (per unit reduced mass)
  if (gt <= 0.0) {
    J = (1.0 + e) * gn * n;
  } else {
    const Vec3 t = Gt / gt;
    if (gn / gt <= 2.0 / (7.0 * f * (1.0 + e))) {
      J = (n + f * t) * (gn * (1.0 + e));  // sliding (eq. 22)
    } else {
      J = (1.0 + e) * gn * n + (2.0 / 7.0) * gt * t;  // sticking (eq. 23)
    }
  }
  vi_out = vi - J * fi;
  vj_out = vj + J * fj;
}

}  // namespace agglo::acoustics
