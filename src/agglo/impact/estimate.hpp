#pragma once
// Cost estimate of the impact commands (collide, vcrit, breakup), from the validated case before any
// run (core/estimate.hpp, docs/limits.md). Upper bounds from the run logic of experiment.cpp:
//   dt          time.dt, or T0 / time.steps_per_period with T0 the shortest contact period among the
//               pairs of the agglomerate and projectile particles and their contacts with the walls
//               (dem::reference_period); the runs use this step (ImpactRun)
//   one run     at speed v takes at most (T_a(v) + after_contact + max_extensions extension) / dt
//               + max_extensions + 2 time steps of n = agglomerate particles + 1, where T_a is
//               time.max_approach or the automatic 5 (gap + r_p) / max(v, 1e-3 m/s) + 1e-4 s
//   relaxation  a charged agglomerate: at most relax_time / dt steps of its particles, once a command;
//               an aggregate projectile's (relax_projectile) once per run
//   vcrit       scan_points runs, then at most ceil(ln(s / tolerance) / ln(points_per_round + 1)) rounds
//               of points_per_round runs (s = scan spacing; each round shrinks the bracket by that
//               factor); bisection speeds lie above v_min, so T_a(v_min) bounds their approach
//   breakup     speeds x samples runs
// Steps are particle-steps: time steps x particles summed over every run; with induced charges (a
// spectral or bem solver and a permittivity unlike the medium's) a step counts kInducedChargeStepWeight
// particle-steps, the measured CPU-time ratio of such a step to a neutral one (docs/limits.md). Memory: the particles, a
// neighbour list of at most kNeighboursPerParticle pairs per particle and the electrostatic solver
// of every concurrent run (`threads` of them in an ensemble), plus for collide the time series and
// snapshots it records in memory (vector capacity up to twice their size). Output: CSV rows, VTK
// snapshots and JSON records of runs, at the writers' number formats.
#include "agglo/core/estimate.hpp"
#include "agglo/impact/impact_case.hpp"

namespace agglo::impact {

// Particle-steps one DEM step with induced charges counts in the step budget (measured: the seed-000
// tetrahedron with kappa_p = 2.5 and 15 costs about 1e3 times the CPU time of the neutral one per step).
inline constexpr double kInducedChargeStepWeight = 1000.0;

// The DEM time step of the runs [s]: time.dt, or the reference period of the launch particles (the
// agglomerate and, unless wall.impact, the projectile; pair and wall contacts) / time.steps_per_period.
double time_step(const ImpactCase& c);
// Upper bound of the time steps of one run at launch speed `speed` (relaxation not included).
double run_steps_bound(const ImpactCase& c, double speed);
// Runs a vcrit search makes at most.
double vcrit_runs_bound(const VcritSpec& v);

Estimate collide_estimate(const ImpactCase& c);
Estimate vcrit_estimate(const ImpactCase& c, int threads);
Estimate breakup_estimate(const ImpactCase& c, int threads);

}  // namespace agglo::impact
