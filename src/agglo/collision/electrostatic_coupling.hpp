#pragma once
// Coupling of an electrostatics solver to the DEM (MODEL.md B.3).
// * Minimum-gap regularisation: the solver sees spheres of radius r_E = r / (1 + g_min/2) with the
//   same charges, so touching particles keep a gap of about g_min r and forces stay finite.
// * Update rule: a new solve runs when some pair's separation vector changed by more than
//   `update_fraction` x its current electrostatic surface gap since the last solve (rigid motions
//   and spins do not trigger solves), or every `update_interval` steps if set; forces and torques
//   are held between solves and every solve warm-starts from the previous one.
// * Optional force scaling chi^(2/5), chi = E_reduced/E_real (for a reduced modulus).
// * When every particle has kappa_p = kappa_0 there is no polarisation: the exact point-charge
//   solver is used whatever solver was chosen (MODEL B.2: "the fast path for kappa_p = 1").
#include <memory>

#include "agglo/dem/external_force.hpp"
#include "agglo/electrostatics/config.hpp"
#include "agglo/electrostatics/solver.hpp"

namespace agglo::collision {

struct CouplingSettings {
  es::EsConfig es;            // [electrostatics]: solver, kappa_0, field, g_min, update rule
  double force_scale = 1.0;   // chi^(2/5) with force_scale_chi, else 1
};

class ElectrostaticForce : public dem::ExternalForce {
 public:
  explicit ElectrostaticForce(const CouplingSettings& s);
  void add_forces(const dem::Particles& p, long step, double time, std::vector<Vec3>& force,
                  std::vector<Vec3>& torque) override;
  double energy() const override { return energy_; }
  long solves() const { return solves_; }
  bool used_fast_path() const { return coulomb_ != nullptr; }
  double seconds() const { return seconds_; }
  const es::Solution& last() const { return last_; }

 private:
  bool needs_solve(const dem::Particles& p, long step) const;
  void solve(const dem::Particles& p, long step);

  CouplingSettings s_;
  std::unique_ptr<es::Solver> solver_;
  std::unique_ptr<es::Solver> coulomb_;  // exact fast path when every kappa_p equals kappa_0
  es::Solution last_;
  std::vector<Vec3> x_at_solve_;
  long step_at_solve_ = -1;
  double energy_ = 0.0;
  long solves_ = 0;
  double seconds_ = 0.0;
};

}  // namespace agglo::collision
