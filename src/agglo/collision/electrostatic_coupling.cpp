#include "agglo/collision/electrostatic_coupling.hpp"

#include "agglo/collision/experiment.hpp"

#include <chrono>
#include <cmath>
#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::collision {

ElectrostaticForce::ElectrostaticForce(const CouplingSettings& s) : s_(s), solver_(es::make_solver(s.es.options)) {}

bool ElectrostaticForce::needs_solve(const dem::Particles& p, long step) const {
  if (x_at_solve_.size() != p.size() || step_at_solve_ < 0) return true;
  if (s_.es.update_interval > 0 && step - step_at_solve_ >= s_.es.update_interval) return true;
  const double shrink = es::electrostatic_radius(1.0, s_.es.min_gap);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      Vec3 now = p.x[j] - p.x[i];
      Vec3 then = x_at_solve_[j] - x_at_solve_[i];
      double gap = norm(now) - shrink * (p.r[i] + p.r[j]);
      if (norm(now - then) > s_.es.update_fraction * gap) return true;
    }
  return false;
}

void ElectrostaticForce::solve(const dem::Particles& p, long step) {
  std::vector<double> radius(p.r.begin(), p.r.end());
  es::Problem prob;
  try {
    prob = es::make_problem(s_.es, p.x, radius, p.q, p.kappa);
  } catch (const NumericalError& e) {
    throw NumericalError(fmt::format("step {}: {} (raise electrostatics.min_gap or lower the impact speed)", step,
                                     e.what()));
  }
  auto t0 = std::chrono::steady_clock::now();
  bool uniform = true;
  for (double k : p.kappa) uniform = uniform && k == s_.es.medium_permittivity;
  if (uniform && !coulomb_) {
    es::SolverOptions o = s_.es.options;
    o.solver = "coulomb";
    coulomb_ = es::make_solver(o);
  }
  last_ = uniform ? coulomb_->solve(prob) : solver_->solve(prob);
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (std::size_t k = 0; k < p.size(); ++k)
    if (!isfinite(last_.force[k]) || !isfinite(last_.torque[k]))
      throw NumericalError(fmt::format("electrostatics: non-finite force on particle {} at step {}", k, step));
  energy_ = last_.energy;
  x_at_solve_ = p.x;
  step_at_solve_ = step;
  ++solves_;
}

void ElectrostaticForce::add_forces(const dem::Particles& p, long step, double, std::vector<Vec3>& force,
                                    std::vector<Vec3>& torque) {
  if (needs_solve(p, step)) solve(p, step);
  for (std::size_t k = 0; k < p.size(); ++k) {
    force[k] += s_.force_scale * last_.force[k];
    torque[k] += s_.force_scale * last_.torque[k];
  }
}

std::unique_ptr<dem::ExternalForce> make_electrostatic_force(const CollisionCase& c) {
  return std::make_unique<ElectrostaticForce>(c.coupling);
}

}  // namespace agglo::collision
