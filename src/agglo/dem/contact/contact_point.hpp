#pragma once
// One active contact as the tangential, rolling and twisting sub-models see it in one evaluation:
// the normal quantities are already final. SI units; F > 0 is repulsive.
#include "agglo/core/vec3.hpp"
#include "agglo/dem/contact/lanes.hpp"

namespace agglo::dem::contact {

struct ContactPoint {
  Vec3 n;              // unit normal from i to j
  double a = 0.0;      // contact radius [m]
  double f_ne = 0.0;   // elastic normal force [N]
  double f_n = 0.0;    // normal force including damping, f_ne + eta_n d(delta)/dt [N]
  double eta_n = 0.0;  // normal damping coefficient [kg/s] (0 without damping)
  Vec3 vs;             // sliding velocity of i relative to j at the contact, in the tangent plane [m/s]
  Vec3 w_rel;          // relative angular velocity w_i - w_j [rad/s]
  double dt = 0.0;     // time step [s] (spring increments)
};

// The same for the fast path's lane forms (lanes.hpp): T is a double or a Lane of pairs.
template <class T>
struct LanePoint {
  lanes::V3<T> n;
  T a{}, f_ne{}, f_n{}, eta_n{};
  lanes::V3<T> vs, w_rel;
  T dt{};
};

}  // namespace agglo::dem::contact
