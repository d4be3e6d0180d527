#pragma once
// Particle state in structure-of-arrays form. Spheres; SI units.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "agglo/core/constants.hpp"
#include "agglo/core/vec3.hpp"

namespace agglo::dem {

struct Particles {
  std::vector<Vec3> x;      // centre [m]
  std::vector<Vec3> v;      // velocity [m/s]
  std::vector<Vec3> w;      // angular velocity [rad/s]
  std::vector<Vec3> f;      // force accumulator [N]
  std::vector<Vec3> t;      // torque accumulator [N m]
  std::vector<double> r;    // radius [m]
  std::vector<double> m;    // mass [kg]
  std::vector<double> I;    // moment of inertia (2/5) m r^2 [kg m^2]
  std::vector<double> q;    // free charge [C]
  std::vector<double> kappa;  // relative permittivity [-]
  std::vector<std::uint32_t> mat;  // material id (0: the default material; dem/material.hpp)

  std::size_t size() const { return x.size(); }

  void add(const Vec3& pos, double radius, double density, const Vec3& vel = {}, double charge = 0.0,
           double permittivity = 1.0, std::uint32_t material = 0) {
    x.push_back(pos);
    v.push_back(vel);
    w.push_back({});
    f.push_back({});
    t.push_back({});
    r.push_back(radius);
    double mass = 4.0 / 3.0 * constants::pi * radius * radius * radius * density;
    m.push_back(mass);
    I.push_back(0.4 * mass * radius * radius);
    q.push_back(charge);
    kappa.push_back(permittivity);
    mat.push_back(material);
  }
};

}  // namespace agglo::dem
