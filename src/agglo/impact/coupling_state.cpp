// Checkpoint state of the electrostatic coupling (coupling_state.hpp).
#include "agglo/impact/coupling_state.hpp"

#include "agglo/impact/electrostatic_coupling.hpp"

namespace agglo::impact {

CouplingState ElectrostaticForce::state() const {
  CouplingState s;
  s.force = last_.force;
  s.torque = last_.torque;
  s.solution_energy = last_.energy;
  s.x_at_solve = x_at_solve_;
  s.visible = visible_;
  s.step_at_solve = step_at_solve_;
  s.energy = energy_;
  s.solves = solves_;
  s.correct = correct_;
  s.f_s = f_s_;
  s.u_s = u_s_;
  s.n_s = n_s_;
  s.prev_force = prev_force_;
  s.prev_torque = prev_torque_;
  s.prev_energy = prev_energy_;
  s.step_at_prev = step_at_prev_;
  s.step_now = step_now_;
  s.fast_path = coulomb_ != nullptr;
  s.warm = solver_->warm_start();
  s.fraction = fraction_;
  s.hold_error = hold_error_;
  return s;
}

void ElectrostaticForce::restore(const CouplingState& s) {
  last_ = es::Solution{};
  last_.force = s.force;
  last_.torque = s.torque;
  last_.energy = s.solution_energy;
  x_at_solve_ = s.x_at_solve;
  visible_ = s.visible;
  step_at_solve_ = s.step_at_solve;
  energy_ = s.energy;
  solves_ = s.solves;
  correct_ = s.correct;
  f_s_ = s.f_s;
  u_s_ = s.u_s;
  n_s_ = s.n_s;
  prev_force_ = s.prev_force;
  prev_torque_ = s.prev_torque;
  prev_energy_ = s.prev_energy;
  step_at_prev_ = s.step_at_prev;
  step_now_ = s.step_now;
  coulomb_.reset();
  if (s.fast_path) make_fast_path();
  solver_->set_warm_start(s.warm);
  fraction_ = s.fraction;
  hold_error_ = s.hold_error;
}

}  // namespace agglo::impact
