#pragma once
// Calibration of one or two model parameters so that observables (e.g. the v_crit of several cases)
// hit target values within tolerances (agglo calibrate, docs/calibrate.md). Method:
//  1. Map: the observables at a grid of grid_points^d parameter values over the box (log-spaced for
//     log-scale parameters), one batch of independent runs.
//  2. Surrogate: per target a robust local regression (lowess.hpp) over every point mapped so far, in
//     the unit box u (u = (x - lo)/(hi - lo), or log(x/lo)/log(hi/lo)); an isolated point off the
//     trend (a run caught in a narrow non-monotonic window of the outcome) gets robustness weight 0,
//     so the fit follows the trend and never a single run. Each local regression spans at least
//     `smoothing` spacings of the first map: zoomed maps add runs (less scatter), not resolution, so
//     a bump narrower than that (runs caught in one narrow non-monotonic window) is never fitted.
//  3. Feasible set: the points of a fine grid (fine_points^d) of the current box where every target
//     is met, |s_k(u) - t_k| <= tol_k; best fit: the minimum of chi2 = sum_k ((s_k - t_k)/tol_k)^2.
//  4. Zoom: refine_rounds more maps of refine_points^d over the feasible set's bounding box (or
//     around the best point when the set is empty), widened by one spacing of the previous map.
//  5. Check: the observables are run at the best fit (achieved values and residuals), optionally
//     with the width of the break-up probability p(v) (v90 - v10 = 2.563 sigma for a normal p)
//     as each observable's uncertainty, propagated to the parameters through the surrogate's
//     Jacobian: cov(x) = (J^T W J)^-1, W = diag(1/sigma_k^2).
// The batches depend only on the configuration and the results, never on the core count.
#include <functional>
#include <string>
#include <vector>

#include "agglo/core/error.hpp"

namespace agglo::calibrate {

using agglo::ConfigError;

struct Parameter {
  std::string key;
  double lower = 0.0, upper = 1.0;
  bool log_scale = false;
  double to_unit(double x) const;
  double from_unit(double u) const;
};

struct Target {
  std::string name;  // e.g. "seed000_neutral_tetrahedron v_crit"
  double value = 0.0, tolerance = 0.0;
};

struct Spec {
  std::vector<Parameter> parameters;  // 1 or 2
  std::vector<Target> targets;        // at least 1
  int grid_points = 7, refine_rounds = 1, refine_points = 5, fine_points = 101;
  double span = 0.3;                  // fraction of the mapped points in each local regression
  double smoothing = 1.5;             // smallest width the surrogate follows, in spacings of the first map
  int robustness_iterations = 2;
  bool check = true;                  // run the observables at the best fit
  bool widths = false;                // ... with the width of p(v)
};

struct Observation {
  double value = 0.0;  // NaN: the run gave no value (e.g. no break-up in the speed range)
  double width = 0.0;  // standard uncertainty from the width of p(v); 0 = not measured
};

// Runs the observables of every target at each parameter point (physical values, one per parameter);
// returns [point][target]. `widths`: also measure the width of p(v).
using Evaluator = std::function<std::vector<std::vector<Observation>>(const std::vector<std::vector<double>>& points,
                                                                      bool widths)>;

struct MapPoint {
  int round = 0;
  std::vector<double> x;                 // parameter values
  std::vector<Observation> observables;  // by target
  std::vector<double> robust_weight;     // by target: weight in the final surrogate
};

struct Result {
  std::vector<MapPoint> points;           // every mapped point, in run order
  std::vector<double> best;               // parameter values of the best fit
  std::vector<double> predicted;          // surrogate observables there, by target
  double chi2 = 0.0;                      // of the surrogate at the best fit
  bool feasible = false;                  // some point meets every target
  std::vector<double> feasible_lo, feasible_hi;  // bounding box of the feasible set (physical)
  std::size_t feasible_points = 0;        // fine-grid points in the set (last box)
  // Points of the feasible set where one parameter is lowest or highest (2 d points, physical; empty
  // when the set is empty): with the best fit, where predictions are run to give them as ranges.
  std::vector<std::vector<double>> feasible_extremes;
  std::vector<Observation> achieved;      // checked at the best fit (empty when not checked)
  // By target: robust scatter (1.4826 x median |run - surrogate|) of the mapped runs within one smoothing
  // width of the best fit: how far a single run (e.g. the check) may fall from the trend there. NaN with
  // fewer than 3 runs.
  std::vector<double> local_scatter;
  std::vector<double> sigma;              // parameter standard uncertainty (NaN: not determined)
  // Surrogate over the whole box for the plots: grid of plot_points^d unit coordinates, values by target.
  std::vector<std::vector<double>> plot_u;
  std::vector<std::vector<double>> plot_values;  // [target][grid point]
  int rounds = 0;
};

// An observable of another case predicted with the calibrated parameters: at the best fit and at the
// feasible set's extreme points, so that the prediction is a range.
struct Prediction {
  std::string name;
  std::vector<std::vector<double>> x;  // parameter points: the best fit first
  std::vector<double> values;          // by point (NaN: no value)
};

// A target outside the range its observable takes over the first map (widened by its tolerance).
struct UnreachableTarget : ConfigError {
  UnreachableTarget(std::size_t k, const std::string& what) : ConfigError(what), target(k) {}
  std::size_t target;
};

// Parameter points the maps of calibrate() evaluate, each once per target (d parameters):
// grid_points^d + refine_rounds x refine_points^d; the check at the best fit adds one more.
double map_points(const Spec& spec);

// Throws UnreachableTarget after the first map when a target cannot be met inside the box.
Result calibrate(const Spec& spec, const Evaluator& evaluate);

// The map of one round: grid of n^d points over the unit sub-box [lo, hi] (per dimension).
std::vector<std::vector<double>> unit_grid(const std::vector<double>& lo, const std::vector<double>& hi, int n);

}  // namespace agglo::calibrate
