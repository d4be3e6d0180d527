#pragma once
// What the contact law reads and writes for one pair: its persistent state, the kinematics of the
// two spheres and the resulting forces. SI units.
#include "agglo/core/vec3.hpp"

namespace agglo::dem {

// Persistent state of a pair (survives neighbour-list rebuilds).
struct ContactState {
  bool active = false;
  double a = 0.0;       // contact radius of the last step (Newton warm start) [m]
  Vec3 xi_t;            // sliding spring displacement [m]
  Vec3 xi_r;            // rolling displacement [m]
  double xi_q = 0.0;    // twisting angle [rad]
  double delta = 0.0;   // overlap of the last evaluation [m] (diagnostics)
};

// Kinematics of the pair as seen by the contact law.
struct PairKinematics {
  Vec3 xi, xj, vi, vj, wi, wj;
  double ri, rj, mi, mj;
};

struct PairForce {
  Vec3 f_on_i;   // force on i (j receives -f_on_i) [N]
  Vec3 t_on_i;   // torque on i about its centre [N m]
  Vec3 t_on_j;   // torque on j about its centre [N m]
};

}  // namespace agglo::dem
