#pragma once
// The complete state of one collision run (impact_run.hpp) between two steps, as plain data for
// checkpoints (impact/checkpoint.hpp, docs/restart.md, "Collide"): the DEM state, the electrostatic coupling
// (held forces, warm start), the recorded rows and snapshots, the phase of the run with its stop
// times and extension count, the output clocks, the energy watchdog's launch values and the agglomerate
// at the launch (the reference of the breakage observables). Restored
// into a run of the same case, the continuation is bitwise identical to the uninterrupted run.
#include "agglo/dem/dem_state.hpp"
#include "agglo/impact/coupling_state.hpp"
#include "agglo/impact/experiment.hpp"

namespace agglo::impact {

// launch: nothing integrated yet; approach: until the projectile touches; contact: after_contact
// and extensions; done: classified.
enum class ImpactPhase : int { launch = 0, approach = 1, contact = 2, done = 3 };

// Where a run stands: phase, contact segment, output clocks and the watchdog's launch values.
struct ImpactProgress {
  ImpactPhase phase = ImpactPhase::launch;
  bool contact = false;             // the projectile has touched
  bool early_stop = false;          // the last contact segment stopped early (clearly broken, intact for good)
  int extensions = 0;               // index of the current contact segment
  double t_contact = 0.0;           // since launch [s]
  double t_stop = 0.0;              // end of the current contact segment (DEM time) [s]
  double t_from = 0.0;              // start of the current contact segment (DEM time) [s]
  double t_launch = 0.0;            // DEM time of the launch [s]
  double next_row = 0.0, next_snap = 0.0;  // output clocks, since launch [s]
  double e_launch = 0.0;            // kinetic + electrostatic energy at launch [J]
  double e_allowed = 0.0;           // largest rise above it the energy watchdog accepts [J]
};

struct ImpactState {
  double speed = 0.0;               // launch speed [m/s]
  dem::DemState dem;
  bool has_coupling = false;        // electrostatics on
  CouplingState coupling;
  Recorder recorder;                // rows and snapshots so far
  ImpactProgress progress;
  dem::Particles launch;            // the agglomerate at the launch, before any step (breakage.hpp)
};

}  // namespace agglo::impact
