#include "agglo/calibrate/lowess.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace agglo::calibrate {

namespace {

double distance(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) s += (a[j] - b[j]) * (a[j] - b[j]);
  return std::sqrt(s);
}

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

Lowess::Lowess(std::vector<std::vector<double>> points, std::vector<double> values, double span,
               int robustness_iterations, double scale_floor, double min_bandwidth)
    : min_h_(min_bandwidth) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (std::isfinite(values[i])) {
      u_.push_back(std::move(points[i]));
      y_.push_back(values[i]);
    }
  dim_ = u_.empty() ? 0 : u_[0].size();
  k_ = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(span * static_cast<double>(y_.size()))),
                               std::min<std::size_t>(y_.size(), 2 * terms(dim_)), y_.size());
  robust_.assign(y_.size(), 1.0);
  for (int it = 0; it < robustness_iterations && y_.size() > 2 * terms(dim_); ++it) {
    std::vector<double> res(y_.size());
    // Residual of each point against the trend of the points at least min_bandwidth / 2 away (the point
    // itself always left out): a narrow cluster cannot vouch for itself.
    for (std::size_t i = 0; i < y_.size(); ++i) res[i] = std::abs(y_[i] - fit(u_[i], robust_, std::max(0.5 * min_h_, 1e-12)));
    const double s = std::max(median(res), scale_floor);
    if (!(s > 0.0)) break;
    for (std::size_t i = 0; i < y_.size(); ++i) {
      const double q = res[i] / (6.0 * s);
      robust_[i] = q < 1.0 ? (1.0 - q * q) * (1.0 - q * q) : 0.0;
    }
  }
}

double Lowess::operator()(const std::vector<double>& u) const { return fit(u, robust_, 0.0); }

double Lowess::fit(const std::vector<double>& u, const std::vector<double>& robust, double exclude) const {
  std::vector<double> r(y_.size()), sorted;
  for (std::size_t i = 0; i < y_.size(); ++i) {
    r[i] = distance(u_[i], u);
    if (r[i] >= exclude) sorted.push_back(r[i]);
  }
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t k = std::min(k_, sorted.size());
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k - 1), sorted.end());
  const double h = std::max({sorted[k - 1] * (1.0 + 1e-9), min_h_, 1e-12});
  // Local quadratic: 1, du_j, du_j du_l (l >= j); the linear and constant fits are fallbacks.
  const auto m = static_cast<Eigen::Index>(terms(dim_));
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(m), x(m);
  double wsum = 0.0, wy = 0.0;
  for (std::size_t i = 0; i < y_.size(); ++i) {
    if (r[i] >= h || r[i] < exclude) continue;
    const double t = 1.0 - std::pow(r[i] / h, 3);
    const double w = t * t * t * robust[i];
    basis(u_[i], u, x);
    A += w * x * x.transpose();
    b += w * y_[i] * x;
    wsum += w;
    wy += w * y_[i];
  }
  if (!(wsum > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  for (const auto n : {m, static_cast<Eigen::Index>(dim_ + 1)}) {
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(A.topLeftCorner(n, n));
    if (lu.rank() == n) return lu.solve(b.head(n))(0);
  }
  return wy / wsum;  // too few distinct points around u: weighted mean
}

std::size_t Lowess::terms(std::size_t d) { return 1 + d + d * (d + 1) / 2; }

void Lowess::basis(const std::vector<double>& ui, const std::vector<double>& u, Eigen::VectorXd& x) {
  const std::size_t d = u.size();
  Eigen::Index k = 0;
  x(k++) = 1.0;
  for (std::size_t j = 0; j < d; ++j) x(k++) = ui[j] - u[j];
  for (std::size_t j = 0; j < d; ++j)
    for (std::size_t l = j; l < d; ++l) x(k++) = (ui[j] - u[j]) * (ui[l] - u[l]);
}

}  // namespace agglo::calibrate
