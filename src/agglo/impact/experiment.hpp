#pragma once
// One collision run (docs/model.md §A.3): optional relaxation of the agglomerate under electrostatics,
// launch of the projectile, integration until `after_contact` after its first contact, break-up
// classification (extended while undecided). The engine records time series and snapshots into a
// Recorder; it never writes files itself.
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "agglo/dem/dem_system.hpp"
#include "agglo/dem/particle_snapshot.hpp"
#include "agglo/impact/breakage.hpp"
#include "agglo/impact/impact_case.hpp"

namespace agglo::impact {

struct TimeseriesRow {
  double t = 0.0;          // time since launch [s]
  double kinetic = 0.0;    // [J]
  double electrostatic = 0.0;  // [J]
  double u_over_u0 = 0.0;  // electrostatic energy / U0, U0 = 2 pi r_p^3 sigma_f^2 / eps0; NaN (undefined) for a list agglomerate
  double rg = 0.0;         // radius of gyration of all particles [m]
  double rg_agglomerate = 0.0;  // radius of gyration of the original agglomerate particles [m]
  int contacts = 0;
};

struct Recorder {
  std::vector<TimeseriesRow> rows;
  std::vector<std::pair<double, dem::ParticleSnapshot>> snapshots;
};

struct Fragment {
  std::vector<int> members;    // particle indices (projectile = last)
  bool escaping = false;
  double separation_rate = 0.0;  // d|x_F - x_rest|/dt [m/s]
  double relative_ke = 0.0;      // 1/2 mu |v_F - v_rest|^2 [J]
  double binding = 0.0;          // point-charge electrostatic binding to the rest (>= 0) [J]
};

// The errors of the held electrostatic forces of an error-controlled coupling (coupling_state.hpp).
struct HoldErrorSummary {
  long measured = 0;     // solves with a measurement; 0: no error control
  double max = 0.0;      // largest relative error
  double mean = 0.0;     // mean relative error
  double fraction = 0.0; // motion threshold at the end (fraction of the gap)
};

struct ImpactOutcome {
  double speed = 0.0;
  bool broken = false;
  bool undecided = false;       // fragments neither escaping nor re-attached after all extensions
  bool contact = false;         // the projectile touched the agglomerate
  std::vector<std::vector<int>> components;  // contact-graph components at the end
  std::vector<Fragment> fragments;            // detached parts of the original agglomerate
  double t_contact = 0.0, t_end = 0.0, dt = 0.0;
  long steps = 0;
  int extensions = 0;
  bool early_stop = false;   // decided before after_contact (clearly broken, or intact for good: intact.hpp)
  long es_solves = 0;        // electrostatic solves
  double es_seconds = 0.0;   // wall time spent in them
  HoldErrorSummary es_hold_error;  // with electrostatics.force_tolerance > 0
  int wall_contacts = -1;    // particles touching a wall at the end (sticking); -1: the case has no wall
  Breakage breakage;         // fragments, damage, restructuring, rebound (breakage.hpp); set when contact
  // Two charged spheres of agglo outcomes (ImpactCase::miss_is_outcome) at the end: relative kinetic plus
  // point-charge Coulomb energy E = mu |v_1 - v_2|^2 / 2 + q_1 q_2 / (4 pi eps0 kappa_0 |x_1 - x_2|) [J];
  // E < 0: the pair is bound and cannot separate for good. NaN otherwise.
  double pair_energy = std::numeric_limits<double>::quiet_NaN();
};

// Electrostatic coupling factory (defined in electrostatic_coupling.cpp).
std::unique_ptr<dem::ExternalForce> make_electrostatic_force(const ImpactCase& c);

// `progress(fraction, simulated time)` is called now and then (may be empty).
using ProgressFn = std::function<void(double, double)>;
// `relaxed`: the agglomerate from relaxed_agglomerate(c) (computed here when null); pass it to
// reuse one relaxation for many speeds. `approach`: the free flight shared by the runs of the case
// (approach_cache.hpp, made from the same `relaxed`; null: each run integrates its own).
class ApproachCache;
ImpactOutcome run_impact(const ImpactCase& c, double speed, Recorder* rec = nullptr,
                               const ProgressFn& progress = {}, const dem::Particles* relaxed = nullptr,
                               ApproachCache* approach = nullptr);

// The agglomerate alone, relaxed under electrostatics (as built when there is none), at rest.
// `progress(fraction of relax_time, simulated time)` every 50 steps (may be empty). The calling thread's
// cancel token is polled every step (core/cancel.hpp). InvalidRunError when the agglomerate as built is
// not one connected contact graph, or when the relaxation changed its contacts (e.g. a field tore it
// apart): the target would not be the agglomerate of the case.
dem::Particles relaxed_agglomerate(const ImpactCase& c, const ProgressFn& progress = {});

// An aggregate projectile relaxed as the target is: with charges or a field (and time.relax_time > 0)
// particles [first, end) of p, the projectile at its launch place (add_projectile), settle alone under
// their own electrostatic and damped contact forces (and the walls) until relaxed as above, then move
// at `speed` along +x without spin. A sphere projectile, or a case without electrostatics: unchanged.
// Every run relaxes its projectile (a random orientation per run turns it first); InvalidRunError as above.
void relax_projectile(const ImpactCase& c, dem::Particles& p, std::size_t first, double speed);

// InvalidRunError (naming `when` and the smallest detached part) unless the active contacts join the
// first `n_agg` particles of `sys` into one component.
void check_one_agglomerate(const dem::DemSystem& sys, std::size_t n_agg, std::string_view when);

// Radius of gyration [(1/N) sum |x_i - x_c|^2]^(1/2) of the first `n` particles (all if n = 0).
double radius_of_gyration(const dem::Particles& p, std::size_t n = 0);

// Classification of the current state (used by run_impact; exposed for tests).
ImpactOutcome classify(const dem::DemSystem& sys, std::size_t n_agglomerate, double medium_permittivity);

}  // namespace agglo::impact
