#include "agglo/collision/electrostatic_coupling.hpp"

#include "agglo/collision/experiment.hpp"

#include <cmath>
#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::collision {

ElectrostaticForce::ElectrostaticForce(const CouplingSettings& s) : s_(s), solver_(es::make_solver(s.solver)) {}

bool ElectrostaticForce::needs_solve(const dem::Particles& p, long step) const {
  if (x_at_solve_.size() != p.size() || step_at_solve_ < 0) return true;
  if (s_.update_interval > 0 && step - step_at_solve_ >= s_.update_interval) return true;
  const double shrink = 1.0 / (1.0 + 0.5 * s_.min_gap);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      Vec3 now = p.x[j] - p.x[i];
      Vec3 then = x_at_solve_[j] - x_at_solve_[i];
      double gap = norm(now) - shrink * (p.r[i] + p.r[j]);
      if (norm(now - then) > s_.update_fraction * gap) return true;
    }
  return false;
}

void ElectrostaticForce::solve(const dem::Particles& p, long step) {
  es::Problem prob;
  prob.medium_permittivity = s_.medium_permittivity;
  prob.external_field = s_.external_field;
  const double shrink = 1.0 / (1.0 + 0.5 * s_.min_gap);
  for (std::size_t k = 0; k < p.size(); ++k) prob.spheres.push_back({p.x[k], p.r[k] * shrink, p.q[k], p.kappa[k]});
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if (norm(p.x[j] - p.x[i]) <= prob.spheres[i].radius + prob.spheres[j].radius)
        throw NumericalError(fmt::format(
            "electrostatics: particles {} and {} overlap by more than the min-gap regularisation at step {} "
            "(overlap {:.3g} m > g_min r); raise electrostatics.min_gap or reduce the impact speed",
            i, j, step, p.r[i] + p.r[j] - norm(p.x[j] - p.x[i])));
  last_ = solver_->solve(prob);
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
