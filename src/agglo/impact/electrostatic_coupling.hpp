#pragma once
// Coupling of an electrostatics solver to the DEM (docs/model.md §B.3).
// * Minimum-gap regularisation: the solver sees spheres of radius r_E = r / (1 + g_min/2) with the
//   same charges, so touching particles keep a gap of about g_min r and forces stay finite.
// * Update rule: a new solve runs when some pair's separation vector changed by more than
//   `update_fraction` x its current electrostatic surface gap since the last solve (rigid motions
//   and spins do not trigger solves), or every `update_interval` steps if set; forces and torques
//   are held between solves and every solve warm-starts from the previous one. With
//   hold = "pair_corrected" (option) the held forces are corrected by the change of each isolated
//   pair's force since the solve (tabulated two-sphere solutions, pair_table.hpp): the rapidly
//   varying two-body part follows every step, only the many-body remainder is held. Measured gain:
//   1.3-2x smaller force error than "constant" in a charged tetrahedron (kappa 15), exact for a pair.
//   With hold = "extrapolated" (option) forces, torques and energy continue the straight line through
//   the last two solutions in the step count, F(s) = F_1 + w (F_1 - F_0), w = (s - s_1) / (s_1 - s_0)
//   limited to w <= 1 (never beyond the line's own span); constant until a second solve, and again
//   whenever the set of particles in the solve changes. Second order in the interval where "constant"
//   is first order (tests/impact/test_coupling.cpp); with error control 4-7x fewer solves in the seed
//   tetrahedra (docs/seed000.md).
// * Error-controlled re-solves (electrostatics.force_tolerance = tol > 0): at every solve after the
//   first, the forces the hold would have applied at that step (held, pair-corrected if chosen) are
//   compared with the new solution: e = max_k |F_k - F_held,k| / max_k |F_k|, the relative error the
//   hold reached over the interval since the last solve (it grows with the motion, so it is largest at
//   the solve). The motion threshold (in place of update_fraction; it starts at 1e-4 of the gap, as
//   nothing is known before the first measurement) is then scaled by 0.5 tol / e (its square root for
//   the extrapolated hold, whose error grows as the motion squared), limited to [1/4, 1.5] per solve
//   and to [1e-5, 1]: the hold error settles near 0.5 tol. The measured errors (count, largest, mean) and
//   the final threshold go to result.json.
// * Optional force scaling chi^(2/5), chi = E_reduced/E_real (for a reduced modulus).
// * When every particle has kappa_p = kappa_0 there is no polarisation: the exact point-charge
//   solver is used whatever solver was chosen (docs/model.md §B.2: the fast path for kappa_p = 1).
// * Uncharged particles with kappa_p = kappa_0 (e.g. the neutral projectile) feel and exert no
//   electrostatic force; they are left out of the solve.
#include <map>
#include <memory>

#include "agglo/impact/coupling_state.hpp"
#include "agglo/impact/pair_table.hpp"
#include "agglo/dem/external_force.hpp"
#include "agglo/dem/wall.hpp"
#include "agglo/electrostatics/config.hpp"
#include "agglo/electrostatics/solver.hpp"

namespace agglo::impact {

struct CouplingSettings {
  es::EsConfig es;            // [electrostatics]: solver, kappa_0, field, g_min, update rule
  double force_scale = 1.0;   // chi^(2/5) with force_scale_chi, else 1
  // At most one grounded conducting wall (wall.grounded). Method of images: every visible sphere gets
  // a mirror sphere (position reflected in the plane, same radius and kappa_p, free charge -q) and the
  // chosen solver solves real and mirror spheres together. The potential of that system is odd under
  // the reflection, so it vanishes on the plane: the forces on the real spheres are those of the
  // grounded-plane problem with every order of polarisation the solver resolves (for the spectral
  // and BEM solvers: the spheres' mutual and self-image polarisation; coulomb: point charges), and the
  // energy of the real system is half the solved one. The update rule also watches each sphere's gap
  // to its own image.
  std::vector<dem::Wall> grounded;
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
  // Errors of the held forces measured at the solves (force_tolerance > 0; empty otherwise).
  const HoldErrorStats& hold_error() const { return hold_error_; }
  const es::Solution& last() const { return last_; }
  // The forces a step at state p applies [N]: the held (pair-corrected) solution times force_scale.
  std::vector<Vec3> applied_forces(const dem::Particles& p);
  // Checkpoint state (coupling_state.hpp); restore() into a coupling of the same settings.
  CouplingState state() const;
  void restore(const CouplingState& s);

 private:
  bool needs_solve(const dem::Particles& p, long step) const;
  std::vector<Vec3> held_forces(const dem::Particles& p, long step);  // what a step without a solve would apply
  double ramp(long step) const;
  void keep_previous(bool same_particles, long step);  // before a solve replaces last_  // extrapolated hold: (step - s) / (s - s_prev); 0 without a previous solve
  void adapt(const std::vector<Vec3>& held);                // measure e against last_, rescale fraction_
  void solve(const dem::Particles& p, long step);
  // Isolated-pair force on j (along i->j, > 0 repulsive) and energy of every pair at the current state.
  void pair_terms(const dem::Particles& p, std::vector<double>& f, std::vector<double>& u, std::vector<Vec3>& n);
  void make_fast_path();  // the exact point-charge solver (coulomb_)
  const PairTable& table_for(const dem::Particles& p, std::size_t i, std::size_t j);

  CouplingSettings s_;
  std::unique_ptr<es::Solver> solver_;
  std::unique_ptr<es::Solver> coulomb_;  // exact fast path when every kappa_p equals kappa_0
  es::Solution last_;
  std::vector<Vec3> x_at_solve_;
  std::vector<std::size_t> visible_;  // particles in the last solve (charged or kappa_p != kappa_0)
  std::vector<std::size_t> was_visible_;  // scratch of solve(): those of the solve before
  // Scratch of solve(), kept between solves so that a solve allocates no arrays of its own.
  std::vector<Vec3> solve_x_;
  std::vector<double> solve_r_, solve_q_, solve_kappa_;
  es::Problem solve_problem_;
  es::Solution solve_out_;
  long step_at_solve_ = -1;
  bool extrapolate_ = false;  // hold = "extrapolated"
  std::vector<Vec3> prev_force_, prev_torque_;  // the solve before the last (extrapolated hold)
  double prev_energy_ = 0.0;
  long step_at_prev_ = -1;  // its step; -1: none (constant hold until the next solve)
  long step_now_ = -1;      // step of the last add_forces
  double fraction_ = 0.0;  // the motion threshold in use (update_fraction, adapted with force_tolerance)
  HoldErrorStats hold_error_;
  double energy_ = 0.0;
  long solves_ = 0;
  bool correct_ = false;                        // pair-corrected hold active for the last solve
  std::vector<double> f_s_, u_s_;               // pair terms at the last solve
  std::vector<Vec3> n_s_;
  std::vector<double> f_now_, u_now_;
  std::vector<Vec3> n_now_;
  std::map<PairKey, std::shared_ptr<const PairTable>> tables_;
  double seconds_ = 0.0;
};

}  // namespace agglo::impact
