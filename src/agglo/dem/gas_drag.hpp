#pragma once
// The surrounding gas of the DEM (docs/model.md §A.6): slip-corrected Stokes drag on every particle
// and a uniform gravity. Each sphere is dragged on its own (no hydrodynamic shielding inside an
// aggregate, no rotational drag):
//   m dv/dt = F + m g - m (v - u) / tau,   tau = m C_c / (3 pi mu_g d),   d = 2 r       [s]
// C_c is the Cunningham correction for the gas's mean free path (core/gas_law.hpp), u the uniform
// flow velocity. The drag is integrated exactly over each half kick of velocity Verlet, with the
// other forces F + m g held at their value (exponential integrator):
//   v <- u + (v - u) E + tau (1 - E) (F/m + g),   E = exp(-h/tau),  h = dt/2,
// so a free sphere decays as exp(-t/tau) and a falling one reaches u + g tau to round-off.
#include "agglo/core/constants.hpp"
#include "agglo/core/gas_law.hpp"
#include "agglo/core/vec3.hpp"

namespace agglo::dem {

struct GasDrag {
  bool enabled = false;
  double viscosity = 0.0;       // mu_g [Pa s]
  double mean_free_path = 0.0;  // lambda_g [m]
  Vec3 flow;                    // u [m/s]

  // Relaxation time of a sphere of mass m [kg] and radius r [m].
  double relaxation_time(double m, double r) const {
    const double d = 2.0 * r;
    return m * gas::cunningham(d, mean_free_path) / (3.0 * constants::pi * viscosity * d);
  }
};

}  // namespace agglo::dem
