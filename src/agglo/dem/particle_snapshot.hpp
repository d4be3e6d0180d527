#pragma once
// The state of every particle at one instant, as recorded for output (impact::Recorder's snapshots):
// centre [m], velocity [m/s], angular velocity [rad/s], radius [m], charge [C] and contact count.
// Written by the result writers as VTK .vtp files and into results.nc (writers/impact.cpp).
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::dem {

struct ParticleSnapshot {
  std::vector<Vec3> position, velocity, angular_velocity;
  std::vector<double> radius, charge;
  std::vector<int> contacts;
};

}  // namespace agglo::dem
