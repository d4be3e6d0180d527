#pragma once
// One collision run as an object (docs/model.md §A.3), in phases: launch (constructor), approach
// until the projectile first touches, contact phase (after_contact, extended while the outcome is
// undecided), classification. run_impact() (experiment.hpp) runs one to the end; a restartable
// caller (agglo collide --checkpoint) asks for state() at step boundaries and restores a saved one
// into a fresh run of the same case before run(). Every step is recorded on the output clock.
// A run that cannot observe the experiment throws InvalidRunError (core/error.hpp): the agglomerate is
// not one connected contact graph at the launch, or the projectile never touches it.
#include <functional>
#include <memory>

#include "agglo/impact/approach_cache.hpp"
#include "agglo/impact/impact_state.hpp"

namespace agglo::impact {

class ImpactRun;
// Called after the launch and after every step, where state() is complete; may throw to stop.
using BoundaryFn = std::function<void(const ImpactRun&)>;

class ImpactRun {
 public:
  // The launch: `agglomerate` (relaxed or as built) plus the projectile at `speed` [m/s].
  ImpactRun(const ImpactCase& c, dem::Particles agglomerate, double speed, Recorder* rec, ProgressFn progress = {});
  ~ImpactRun();
  ImpactRun(const ImpactRun&) = delete;
  ImpactRun& operator=(const ImpactRun&) = delete;

  // Replaces the launch state by `s`, a state() of a run of the same case.
  void restore(const ImpactState& s);
  ImpactState state() const;
  // Integrates to the classification (continuing a restored state) and returns the outcome.
  ImpactOutcome run(const BoundaryFn& boundary = {});

  // Runs of one case may share their free flight before contact (approach_cache.hpp): set before run().
  void share_free_flight(ApproachCache* cache) { approach_ = cache; }
  // Steps of the free flight taken from that cache instead of integrated (0: none).
  long shared_steps() const { return shared_steps_; }

  double since_launch() const { return sys_.time() - at_.t_launch; }
  long steps() const { return sys_.steps(); }
  bool finished() const { return at_.phase == ImpactPhase::done; }

 private:
  void launch();
  void skip_free_flight(ApproachCache& cache);  // approach_cache.cpp
  bool projectile_clear(const ApproachCache::Kept& k, Vec3& x) const;
  void advance();
  void approach_step();
  void end_approach(bool touched);
  [[noreturn]] void missed() const;
  void contact_step();
  void end_segment(bool early);
  ImpactOutcome outcome() const;
  Breakage breakage() const;
  void set_launch(dem::Particles agglomerate);
  void step();
  void guard() const;
  double watched_energy() const;
  void arm_watchdog();
  void check_energy() const;
  bool projectile_touches() const;
  bool intact_for_good();  // the agglomerate can no longer break (intact.hpp)
  void record();

  const ImpactCase& c_;
  double speed_;  // launch speed of the projectile [m/s]
  dem::DemSystem sys_;
  std::size_t n_agg_;  // the projectile is particle n_agg_ (an aggregate projectile: n_agg_ and above)
  Recorder* rec_;
  ProgressFn progress_;
  std::unique_ptr<dem::ExternalForce> es_;
  double u0_ = 0.0;      // U0 = 2 pi r_p^3 sigma_f^2 / eps0 [J]; NaN for a list agglomerate
  double kappa0_ = 1.0;  // medium permittivity of the point-charge binding
  double max_approach_ = 0.0;  // longest approach [s]
  bool intact_stop_ = false;   // time.intact_stop applies to this run
  ImpactProgress at_;  // phase, segment, output clocks, watchdog
  dem::Particles launch_agg_;               // the agglomerate at the launch, at rest (breakage.hpp)
  std::vector<ContactEdge> launch_edges_;   // its contacts
  ApproachCache* approach_ = nullptr;       // the case's shared free flight, if any
  long shared_steps_ = 0;
};

// The case's DEM parameters with the time step of its runs (time_step: the projectile, added after the
// system is built, included).
dem::DemParams run_params(const ImpactCase& c);

// Adds the likely input cause to a DEM blow-up message (experiment.cpp).
[[noreturn]] void rethrow_with_cause(const dem::DemInstability& e);

}  // namespace agglo::impact
