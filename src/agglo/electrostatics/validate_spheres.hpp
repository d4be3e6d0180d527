#pragma once
// Physical validity of a solver input (docs/model.md §B.1), checked by every solver before it
// solves: medium permittivity kappa_0 > 0 and finite; applied field finite; for every sphere a
// radius > 0, a relative permittivity kappa_p > 0 (both finite), a finite centre and charge; and no
// two spheres overlapping or touching, |x_i - x_k| > a_i + a_k (the radii are the electrostatic
// radii the solver sees). A violation throws InvalidSpheres. Its message speaks about the physics
// only (spheres are numbered as in Problem::spheres); callers that read input files map `reason`
// and the sphere indices to their own keys and particle numbers.
#include <string>

#include "agglo/core/error.hpp"
#include "agglo/electrostatics/solver.hpp"

namespace agglo::es {

struct InvalidSpheres : NumericalError {
  enum class Reason { medium_permittivity, external_field, radius, permittivity, non_finite, overlap };
  InvalidSpheres(Reason r, int first, int second, const std::string& detail);
  Reason reason;
  int first = -1, second = -1;  // sphere indices involved (-1: none; second only for overlap)
  std::string detail;           // the message without the leading "electrostatics: "
};

void validate_spheres(const Problem& p);

}  // namespace agglo::es
