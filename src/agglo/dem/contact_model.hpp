#pragma once
// Adhesive contact between two spheres (MODEL.md A.2): JKR normal force with Marshall's hysteresis
// (a contact forms at delta >= 0 and breaks below -delta_C, or at the force minimum -F_C with the
// LAMMPS rule), normal damping F_nd = -alpha(e) sqrt(m* k_N) d(delta)/dt on every active contact,
// and a tangential sub-model selected by name:
//   "seed"     F_t = -min(mu_F |F_n|, eta_t |v_s|) v_s/|v_s|, eta_t = eta_N  (Ruan & Li 2022, eq. 2b,
//              regularised near zero slip); no rolling or twisting resistance.
//   "marshall" sliding spring k_T = 8 G* a, damping eta_T = eta_N, Coulomb limit mu_F |F_ne + 2 F_C|
//              (Marshall 2009), plus optional twisting (k_Q = k_T a^2/2, eta_Q = eta_T a^2/2, limit
//              2/3 a mu_F |F_ne + 2 F_C|) and rolling (moment k_R |xi_R|, k_R = 4 F_C (a/a0)^(3/2),
//              rolling displacement limited to theta_crit R).
// Torque levers are the distances from each centre to the contact plane (l_i + l_j = |x_j - x_i|),
// which equal r_i at touching and conserve angular momentum exactly.
#include <cstdint>
#include <string>

#include "agglo/core/vec3.hpp"
#include "agglo/dem/jkr.hpp"

namespace agglo::dem {

enum class BreakRule { marshall, lammps };
enum class TangentialModel { seed, marshall };

struct ContactParams {
  double youngs_modulus = 1.0e9;   // E [Pa]
  double poisson_ratio = 0.33;     // nu [-]
  double surface_energy = 0.01;    // gamma [J/m^2]
  double restitution = 0.7;        // e in (0, 1]; alpha(e) damping
  double friction = 0.3;           // mu_F [-]
  TangentialModel tangential = TangentialModel::seed;
  bool rolling = false;            // marshall only
  bool twisting = false;           // marshall only
  double rolling_angle = 0.01;     // critical rolling angle theta_crit [rad]
  BreakRule break_rule = BreakRule::marshall;
  bool damping = true;             // switch normal/tangential damping off (analytic checks)

  double estar() const;  // like materials: E / (2 (1 - nu^2))
  double gstar() const;  // like materials: G / (2 (2 - nu)), G = E / (2 (1 + nu))
};

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

// One contact evaluation: updates `s` (formation, break, springs) and returns the forces.
// `jkr` and `alpha` are the pair's precomputed JKR constants and damping coefficient.
PairForce contact_force(const ContactParams& p, const JkrPair& jkr, double alpha, const PairKinematics& k,
                        ContactState& s, double dt);

// Overlap below which an active contact breaks (positive number: break when delta < -this).
double break_separation(const ContactParams& p, const JkrPair& jkr);

}  // namespace agglo::dem
