#pragma once
// ParaView output of particles: VTK XML PolyData (.vtp, ASCII) with one vertex per particle and
// point data (radius, velocity, angular velocity, charge, contact count), plus a .pvd collection
// that lists the snapshots with their times.
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::io {

struct ParticleSnapshot {
  std::vector<Vec3> position, velocity, angular_velocity;
  std::vector<double> radius, charge;
  std::vector<int> contacts;
};

void write_vtp(std::ostream& out, const ParticleSnapshot& s);
// files: (time [s], file name relative to the .pvd)
void write_pvd(std::ostream& out, const std::vector<std::pair<double, std::string>>& files);

}  // namespace agglo::io
