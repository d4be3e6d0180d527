#pragma once
// Break-up probability of an agglomerate vs projectile speed. Near the threshold the outcome of one
// collision is non-monotonic in the speed (fragments recaptured, chaotic contact sequences), so the
// single-trajectory v_crit of vcrit.hpp depends on which speeds a scan happens to test. This
// observable runs, at each speed, M collisions whose lateral impact offset is spread evenly over
// offset_radii +- offset_spread (stratified: offset_k = offset + spread (2(k + 1/2)/M - 1), no random
// numbers), for each of breakup.orientations rigid rotations of the agglomerate (orientation_set.hpp:
// a stratified covering of all orientations, so p(v) is orientation-averaged; 1 = the agglomerate as
// oriented), and reports the fraction that breaks with its Wilson 95 % interval, and the speeds at which
// the fraction first reaches 0.1, 0.5 and 0.9 (linear interpolation between tested speeds); and, per
// speed, the mean damage ratio and largest-fragment fraction of its runs (breakage.hpp) with their
// standard errors s = sqrt(sum (x_i - mean)^2 / ((n - 1) n)) over the n runs (orientations x offsets;
// NaN for n = 1).
#include <functional>
#include <vector>

#include "agglo/impact/experiment.hpp"

namespace agglo::impact {

struct BreakupPoint {
  double speed = 0.0;                      // [m/s]
  int runs = 0, broken = 0, undecided = 0;  // undecided outcomes count as not broken (as in vcrit)
  double p = 0.0;                          // broken / runs
  double ci_lo = 0.0, ci_hi = 0.0;         // Wilson score interval, 95 %
  double damage = 0.0, damage_se = 0.0;    // mean damage ratio and its standard error [1]
  double largest = 0.0, largest_se = 0.0;  // mean largest-fragment fraction and its standard error [1]
};

struct BreakupResult {
  std::vector<BreakupPoint> points;        // sorted by speed
  std::vector<double> offsets;             // offsets used at every speed and orientation [r_p]
  int orientations = 1;                    // rotations of the agglomerate (orientation_set.hpp)
  double v10 = -1.0, v50 = -1.0, v90 = -1.0;  // first speed where p reaches 0.1 / 0.5 / 0.9; -1 if never
  std::vector<ImpactOutcome> outcomes;  // every run, speed-major, then orientation, offset-minor
};

// One impact of the ensemble: projectile speed [m/s], lateral offset [r_p], and rotation
// `orientation` of the stratified set of `orientations` (stratified_orientation(orientation,
// orientations)) applied rigidly to the agglomerate; orientations = 1: the agglomerate as oriented.
struct ImpactJob {
  double speed = 0.0, offset_radii = 0.0;
  int orientation = 0, orientations = 1;
  bool bisection = false;  // a run of a v_crit bisection (TimeSpec::bisection)
};
// Runs independent impacts and returns their outcomes in the same order (e.g. run::ensemble_impacts:
// in parallel, journaled; results do not depend on the thread count).
using ImpactBatch = std::function<std::vector<ImpactOutcome>(const std::vector<ImpactJob>& jobs)>;

// The jobs of a break-up curve: speeds sorted ascending (speed-major), then the orientations, offsets
// stratified (minor).
std::vector<ImpactJob> breakup_jobs(const BreakupSpec& spec, double offset_radii);
BreakupResult breakup_probability(const BreakupSpec& spec, double offset_radii, const ImpactBatch& run_batch);

// Wilson score interval for k successes in n trials (z = 1.96).
void wilson_interval(int k, int n, double& lo, double& hi);

// First speed at which the piecewise-linear p(v) reaches `level` (-1 if it never does).
double first_crossing(const std::vector<BreakupPoint>& pts, double level);

}  // namespace agglo::impact
