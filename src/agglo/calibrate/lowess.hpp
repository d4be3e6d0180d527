#pragma once
// Robust local regression (LOWESS, Cleveland 1979) of scattered data y_i at points u_i of the unit
// box [0, 1]^d (d = 1 or 2): the surrogate of an observable over the calibration parameters.
// At a point u the fit is a weighted local quadratic regression
//   y ~ a + b.(u_i - u) + (u_i - u)^T C (u_i - u)
// over the k = max(ceil(span n), 2 x terms) nearest data points, with tricube distance weights
// (1 - (r_i/h)^3)^3 (h: distance of the k-th nearest, times 1 + 1e-9, but at least min_bandwidth) times
// robustness weights; the value is a. min_bandwidth is the smallest feature the surrogate can follow:
// a bump narrower than it (several runs caught in one narrow window) is averaged with its neighbours
// or rejected, never fitted. Robustness iterations (bisquare): after a pass, each point's residual e_i
// against the fit at u_i from the points at least max(min_bandwidth / 2, 0+) away gives r_i = (1 - (e_i / 6s)^2)^2 for |e_i| < 6s, else 0, with
// s = max(median |e|, scale_floor). An isolated point off the trend (e.g. a run whose outcome hit a
// narrow non-monotonic window) thus gets weight 0 and does not bend the surrogate; scale_floor keeps
// genuine scatter of the size of the target tolerance from being treated as outliers.
#include <vector>

#include <Eigen/Dense>

namespace agglo::calibrate {

class Lowess {
 public:
  // points: n x d coordinates in [0, 1]; values: n observables (non-finite ones are left out).
  Lowess(std::vector<std::vector<double>> points, std::vector<double> values, double span, int robustness_iterations,
         double scale_floor, double min_bandwidth = 0.0);

  double operator()(const std::vector<double>& u) const;
  // Robustness weight of data point i (1 = fully used, 0 = rejected as an outlier).
  double weight(std::size_t i) const { return robust_[i]; }
  std::size_t size() const { return y_.size(); }

 private:
  // The local fit at u from the points at distance >= exclude (0: all of them).
  double fit(const std::vector<double>& u, const std::vector<double>& robust, double exclude) const;
  static std::size_t terms(std::size_t d);  // coefficients of a quadratic in d variables
  static void basis(const std::vector<double>& ui, const std::vector<double>& u, Eigen::VectorXd& x);
  std::vector<std::vector<double>> u_;
  std::vector<double> y_;
  std::vector<double> robust_;
  std::size_t k_ = 0;
  double min_h_ = 0.0;
  std::size_t dim_ = 0;
};

}  // namespace agglo::calibrate
