#pragma once
// The state of the electrostatic coupling (electrostatic_coupling.hpp) between two steps, as plain
// data for checkpoints: the held forces and torques of the last solve, the positions and step of that
// solve (update rule), the pair terms of the pair-corrected hold, the solver's warm start, counters.
// The two-sphere tables are a cache rebuilt identically on demand and are not part of it, nor is the
// wall time spent solving (a restored coupling counts its own; equal states give equal checkpoints).
#include <cstddef>
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/electrostatics/solver.hpp"

namespace agglo::impact {

// The errors of the held forces measured at the solves of an error-controlled coupling
// (electrostatic_coupling.hpp): relative to the largest electrostatic force at each solve.
struct HoldErrorStats {
  long measured = 0;        // solves with a measurement (every solve after the first)
  double max = 0.0;         // largest relative error
  double sum = 0.0;         // sum of the relative errors (mean = sum / measured)
  double fraction = 0.0;    // motion threshold after the last solve (fraction of the gap)
};

struct CouplingState {
  std::vector<Vec3> force, torque;    // held solution of the last solve [N], [N m]
  double solution_energy = 0.0;       // energy of the last solve [J]
  std::vector<Vec3> x_at_solve;       // positions at the last solve [m]
  std::vector<std::size_t> visible;   // particles in the last solve
  long step_at_solve = -1;
  double energy = 0.0;                // energy reported after the last evaluation [J]
  long solves = 0;
  bool correct = false;               // pair-corrected hold active
  std::vector<double> f_s, u_s;       // pair terms at the last solve
  std::vector<Vec3> n_s;
  bool fast_path = false;             // the exact point-charge solver has been made
  std::vector<Vec3> prev_force, prev_torque;  // the solve before the last (extrapolated hold) [N], [N m]
  double prev_energy = 0.0;           // its energy [J]
  long step_at_prev = -1;             // its step; -1: none
  long step_now = -1;                 // step of the last force evaluation
  es::WarmStart warm;                 // of the chosen solver
  double fraction = 0.0;              // motion threshold in use
  HoldErrorStats hold_error;
};

}  // namespace agglo::impact
