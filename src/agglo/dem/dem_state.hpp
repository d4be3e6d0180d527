#pragma once
// The complete state of a DemSystem between two steps, as plain data (checkpoints, docs/restart.md, "Collide"):
// everything the next step reads. Restoring it into a system built from the same case continues the
// run bitwise identically: the particles with the forces of the current positions (the next step
// starts with the second half-kick of velocity Verlet, so the forces are not recomputed), the contact
// states of every listed pair and of every particle with each wall (JKR contact radius = Newton warm
// start, spring displacements), the
// neighbour list and the positions it was built at (its next rebuild happens at the same step).
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/dem/neighbor_list.hpp"
#include "agglo/dem/particles.hpp"
#include "agglo/dem/wall.hpp"

namespace agglo::dem {

struct NeighborState {
  std::vector<Pair> pairs;       // sorted (i, j) with their contact states and JKR constants
  std::vector<Vec3> x_at_build;  // positions at the last build [m]
  long builds = 0;
};

struct DemState {
  Particles particles;           // all fields, force and torque accumulators included
  NeighborState neighbors;
  double dt = 0.0;               // time step [s]
  double skin = 0.0;             // neighbour skin [m]
  double time = 0.0;             // simulated time [s]
  long step = 0;
  bool forces_ready = false;     // particles.f/t hold the forces of the current positions
  std::vector<WallContacts> walls;  // contact states with each wall (DemParams::walls)
};

}  // namespace agglo::dem
