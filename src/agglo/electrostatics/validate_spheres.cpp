#include "agglo/electrostatics/validate_spheres.hpp"

#include <cmath>

#include <fmt/format.h>

namespace agglo::es {

InvalidSpheres::InvalidSpheres(Reason r, int i, int k, const std::string& d)
    : NumericalError("electrostatics: " + d), reason(r), first(i), second(k), detail(d) {}

namespace {

bool positive_finite(double v) { return v > 0.0 && std::isfinite(v); }

void validate_sphere(const Sphere& s, int i) {
  using R = InvalidSpheres::Reason;
  if (!positive_finite(s.radius))
    throw InvalidSpheres(R::radius, i, -1, fmt::format("sphere {} has radius {} m (must be > 0)", i, s.radius));
  if (!positive_finite(s.permittivity))
    throw InvalidSpheres(R::permittivity, i, -1,
                         fmt::format("sphere {} has relative permittivity {} (must be > 0)", i, s.permittivity));
  if (!isfinite(s.center) || !std::isfinite(s.charge))
    throw InvalidSpheres(R::non_finite, i, -1, fmt::format("sphere {} has a non-finite position or charge", i));
}

}  // namespace

void validate_spheres(const Problem& p) {
  using R = InvalidSpheres::Reason;
  if (!positive_finite(p.medium_permittivity))
    throw InvalidSpheres(R::medium_permittivity, -1, -1,
                         fmt::format("medium relative permittivity is {} (must be > 0)", p.medium_permittivity));
  if (!isfinite(p.external_field)) throw InvalidSpheres(R::external_field, -1, -1, "applied field is not finite");
  const int n = static_cast<int>(p.spheres.size());
  for (int i = 0; i < n; ++i) validate_sphere(p.spheres[i], i);
  for (int i = 0; i < n; ++i)
    for (int k = i + 1; k < n; ++k) {
      const Sphere& a = p.spheres[i];
      const Sphere& b = p.spheres[k];
      const double s = a.radius + b.radius;
      if (norm2(a.center - b.center) <= s * s)  // the distance itself only for the message
        throw InvalidSpheres(R::overlap, i, k,
                             fmt::format("spheres {} and {} overlap or touch (centre distance {:.6g} m <= sum of "
                                         "radii {:.6g} m)",
                                         i, k, norm(a.center - b.center), s));
    }
}

}  // namespace agglo::es
