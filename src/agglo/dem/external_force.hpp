#pragma once
// Hook for non-contact forces (electrostatics, drag, fields). Called once per step after the
// contact forces, with the positions of that step; adds to the force/torque accumulators.
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/dem/particles.hpp"

namespace agglo::dem {

class ExternalForce {
 public:
  virtual ~ExternalForce() = default;
  virtual void add_forces(const Particles& p, long step, double time, std::vector<Vec3>& force,
                          std::vector<Vec3>& torque) = 0;
  // Potential energy of the interaction at the last evaluation [J].
  virtual double energy() const = 0;
};

}  // namespace agglo::dem
