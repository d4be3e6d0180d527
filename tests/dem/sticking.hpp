#pragma once
// Shared by the sticking-velocity tests (test_dem_dynamics.cpp, test_wall.cpp, test_materials.cpp): a
// sample material (Sample), DEM parameters resolving the contact finely, and the bisection of the
// largest speed that sticks.
#include <gtest/gtest.h>

#include <functional>

#include "agglo/core/constants.hpp"
#include "agglo/dem/contact/builtin_models.hpp"
#include "agglo/dem/dem_system.hpp"

namespace agglo::dem::testing {

struct Sample {
  double r = 10e-6, rho = 2500, E = 1e9, nu = 0.33, gamma = 0.01;
  double mass() const { return 4.0 / 3.0 * constants::pi * r * r * r * rho; }
};

inline DemParams params_for(const Sample& m, double e, bool damping) {
  DemParams p;
  p.contact.youngs_modulus = m.E;
  p.contact.poisson_ratio = m.nu;
  p.contact.surface_energy = m.gamma;
  p.contact.restitution = e;
  p.contact.models.damping = damping ? contact::AlphaDamping::name : contact::NoDamping::name;
  p.contact.friction = 0.0;
  p.steps_per_period = 1600;  // resolve the contact well: the reference values are for the continuous ODE
  return p;
}

// Largest speed at which `sticks` holds, bisected to 1e-4 relative inside [lo, hi].
inline double bisect(const std::function<bool(double)>& sticks, double lo, double hi) {
  EXPECT_TRUE(sticks(lo));
  EXPECT_FALSE(sticks(hi));
  while (hi - lo > 1e-4 * hi) {
    const double mid = 0.5 * (lo + hi);
    (sticks(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace agglo::dem::testing
