#include "agglo/calibrate/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "agglo/calibrate/lowess.hpp"
#include "agglo/core/error.hpp"

namespace agglo::calibrate {

double Parameter::to_unit(double x) const {
  return log_scale ? std::log(x / lower) / std::log(upper / lower) : (x - lower) / (upper - lower);
}

double Parameter::from_unit(double u) const {
  return log_scale ? lower * std::pow(upper / lower, u) : lower + u * (upper - lower);
}

std::vector<std::vector<double>> unit_grid(const std::vector<double>& lo, const std::vector<double>& hi, int n) {
  auto at = [&](std::size_t j, int i) { return n == 1 ? 0.5 * (lo[j] + hi[j]) : lo[j] + (hi[j] - lo[j]) * i / (n - 1); };
  std::vector<std::vector<double>> g;
  if (lo.size() == 1) {
    for (int i = 0; i < n; ++i) g.push_back({at(0, i)});
  } else {
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k) g.push_back({at(0, i), at(1, k)});
  }
  return g;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Scan {
  std::vector<double> best_u, lo, hi;  // best point; bounding box of the feasible points (unit)
  std::vector<std::vector<double>> lo_at, hi_at;  // feasible points where each parameter is lowest / highest
  double chi2 = std::numeric_limits<double>::infinity();
  std::size_t feasible = 0;
};

class Calibrator {
 public:
  Calibrator(const Spec& s, const Evaluator& e) : spec_(s), evaluate_(e), d_(s.parameters.size()) {}

  Result run() {
    std::vector<double> lo(d_, 0.0), hi(d_, 1.0);
    double spacing = 1.0 / std::max(1, spec_.grid_points - 1);
    map(unit_grid(lo, hi, spec_.grid_points), 0);
    fit_surrogates();
    check_reachable();
    Scan sc = scan(lo, hi);
    for (int r = 1; r <= spec_.refine_rounds; ++r) {
      zoom(sc, spacing, lo, hi);
      spacing = (hi[0] - lo[0]) / std::max(1, spec_.refine_points - 1);
      map(unit_grid(lo, hi, spec_.refine_points), r);
      fit_surrogates();
      sc = scan(lo, hi);
      res_.rounds = r;
    }
    finish(sc);
    return std::move(res_);
  }

 private:
  std::vector<double> physical(const std::vector<double>& u) const {
    std::vector<double> x(d_);
    for (std::size_t j = 0; j < d_; ++j) x[j] = spec_.parameters[j].from_unit(u[j]);
    return x;
  }

  void map(const std::vector<std::vector<double>>& us, int round) {
    std::vector<std::vector<double>> xs;
    for (const auto& u : us) xs.push_back(physical(u));
    const auto obs = evaluate_(xs, false);
    for (std::size_t i = 0; i < xs.size(); ++i) {
      res_.points.push_back({round, xs[i], obs[i], {}});
      u_.push_back(us[i]);
    }
  }

  void fit_surrogates() {
    surrogates_.clear();
    for (std::size_t k = 0; k < spec_.targets.size(); ++k) {
      std::vector<double> y;
      for (const auto& p : res_.points) y.push_back(p.observables[k].value);
      surrogates_.emplace_back(u_, y, spec_.span, spec_.robustness_iterations, 0.5 * spec_.targets[k].tolerance,
                               spec_.smoothing / std::max(1, spec_.grid_points - 1));
    }
  }

  std::vector<double> predict(const std::vector<double>& u) const {
    std::vector<double> s;
    for (const auto& f : surrogates_) s.push_back(f(u));
    return s;
  }

  double chi2(const std::vector<double>& s, bool& met) const {
    double c = 0.0;
    met = true;
    for (std::size_t k = 0; k < s.size(); ++k) {
      const double z = (s[k] - spec_.targets[k].value) / spec_.targets[k].tolerance;
      met = met && std::abs(z) <= 1.0;
      c += z * z;
    }
    return std::isfinite(c) ? c : std::numeric_limits<double>::infinity();
  }

  // A target outside the range its observable takes over the first map (widened by its tolerance).
  void check_reachable() const {
    for (std::size_t k = 0; k < spec_.targets.size(); ++k) {
      double mn = std::numeric_limits<double>::infinity(), mx = -mn;
      for (const auto& p : res_.points)
        if (std::isfinite(p.observables[k].value)) {
          mn = std::min(mn, p.observables[k].value);
          mx = std::max(mx, p.observables[k].value);
        }
      const auto& t = spec_.targets[k];
      if (!(t.value >= mn - t.tolerance && t.value <= mx + t.tolerance))
        throw UnreachableTarget(k, fmt::format("unreachable: over the parameter box {} ranges over [{:g}, {:g}] "
                                               "(tolerance {:g}); widen the [[parameter]] ranges",
                                               t.name, mn, mx, t.tolerance));
    }
  }

  Scan scan(const std::vector<double>& lo, const std::vector<double>& hi) const {
    Scan sc;
    sc.lo.assign(d_, 1.0);
    sc.hi.assign(d_, 0.0);
    sc.lo_at.assign(d_, {});
    sc.hi_at.assign(d_, {});
    for (const auto& u : unit_grid(lo, hi, spec_.fine_points)) {
      bool met = false;
      const double c = chi2(predict(u), met);
      if (c < sc.chi2 || sc.best_u.empty()) {
        sc.chi2 = c;
        sc.best_u = u;
      }
      if (!met) continue;
      ++sc.feasible;
      for (std::size_t j = 0; j < d_; ++j) {
        if (sc.lo_at[j].empty() || u[j] < sc.lo[j]) sc.lo_at[j] = u;
        if (sc.hi_at[j].empty() || u[j] > sc.hi[j]) sc.hi_at[j] = u;
        sc.lo[j] = std::min(sc.lo[j], u[j]);
        sc.hi[j] = std::max(sc.hi[j], u[j]);
      }
    }
    return sc;
  }

  void zoom(const Scan& sc, double spacing, std::vector<double>& lo, std::vector<double>& hi) const {
    for (std::size_t j = 0; j < d_; ++j) {
      const double a = sc.feasible ? sc.lo[j] : sc.best_u[j], b = sc.feasible ? sc.hi[j] : sc.best_u[j];
      lo[j] = std::max(0.0, a - spacing);
      hi[j] = std::min(1.0, b + spacing);
    }
  }

  void finish(const Scan& sc);
  void scatter_near_best(const std::vector<double>& best_u);
  void uncertainty(const std::vector<double>& sigma_obs);
  std::vector<double> parameters_unit() const {
    std::vector<double> u(d_);
    for (std::size_t j = 0; j < d_; ++j) u[j] = spec_.parameters[j].to_unit(res_.best[j]);
    return u;
  }

  const Spec& spec_;
  const Evaluator& evaluate_;
  const std::size_t d_;
  Result res_;
  std::vector<std::vector<double>> u_;  // unit coordinates of res_.points
  std::vector<Lowess> surrogates_;
};

void Calibrator::finish(const Scan& sc) {
  res_.best = physical(sc.best_u);
  res_.predicted = predict(sc.best_u);
  res_.chi2 = sc.chi2;
  res_.feasible = sc.feasible > 0;
  res_.feasible_points = sc.feasible;
  if (res_.feasible) {
    res_.feasible_lo = physical(sc.lo);
    res_.feasible_hi = physical(sc.hi);
    for (std::size_t j = 0; j < d_; ++j) {
      res_.feasible_extremes.push_back(physical(sc.lo_at[j]));
      res_.feasible_extremes.push_back(physical(sc.hi_at[j]));
    }
  }
  // Surrogates skip non-finite values: finite[k] counts the finite ones so far (the surrogate's index).
  std::vector<std::size_t> finite(surrogates_.size(), 0);
  for (auto& p : res_.points)
    for (std::size_t k = 0; k < surrogates_.size(); ++k)
      p.robust_weight.push_back(std::isfinite(p.observables[k].value) ? surrogates_[k].weight(finite[k]++) : 0.0);
  scatter_near_best(sc.best_u);
  const std::vector<double> lo(d_, 0.0), hi(d_, 1.0);
  res_.plot_u = unit_grid(lo, hi, std::min(spec_.fine_points, 61));
  res_.plot_values.assign(surrogates_.size(), {});
  for (const auto& u : res_.plot_u)
    for (std::size_t k = 0; k < surrogates_.size(); ++k) res_.plot_values[k].push_back(surrogates_[k](u));
  std::vector<double> sigma_obs;
  for (const auto& t : spec_.targets) sigma_obs.push_back(t.tolerance);
  if (spec_.check) {
    res_.achieved = evaluate_({res_.best}, spec_.widths)[0];
    for (std::size_t k = 0; k < sigma_obs.size(); ++k)
      if (res_.achieved[k].width > 0.0) sigma_obs[k] = res_.achieved[k].width;
  }
  uncertainty(sigma_obs);
}

void Calibrator::scatter_near_best(const std::vector<double>& best_u) {
  const double width = spec_.smoothing / std::max(1, spec_.grid_points - 1);
  for (std::size_t k = 0; k < surrogates_.size(); ++k) {
    std::vector<double> dev;
    for (std::size_t i = 0; i < res_.points.size(); ++i) {
      double r2 = 0.0;
      for (std::size_t j = 0; j < d_; ++j) r2 += (u_[i][j] - best_u[j]) * (u_[i][j] - best_u[j]);
      const double y = res_.points[i].observables[k].value;
      if (std::sqrt(r2) <= width && std::isfinite(y)) dev.push_back(std::abs(y - surrogates_[k](u_[i])));
    }
    if (dev.size() < 3) {
      res_.local_scatter.push_back(kNaN);
      continue;
    }
    std::nth_element(dev.begin(), dev.begin() + static_cast<std::ptrdiff_t>(dev.size() / 2), dev.end());
    res_.local_scatter.push_back(1.4826 * dev[dev.size() / 2]);
  }
}

// sigma of the parameters from the surrogate's Jacobian at the best fit: cov = (J^T W J)^-1, computed in the
// unit coordinates (well scaled) and taken to the parameters' units with dx/du.
void Calibrator::uncertainty(const std::vector<double>& sigma_obs) {
  const auto nt = static_cast<Eigen::Index>(spec_.targets.size()), nd = static_cast<Eigen::Index>(d_);
  Eigen::MatrixXd J(nt, nd);
  std::vector<double> dxdu(d_);
  const double h = 1e-3;
  for (std::size_t j = 0; j < d_; ++j) {
    std::vector<double> a = parameters_unit(), b = a;
    a[j] = std::max(0.0, a[j] - h);
    b[j] = std::min(1.0, b[j] + h);
    const auto sa = predict(a), sb = predict(b);
    dxdu[j] = (spec_.parameters[j].from_unit(b[j]) - spec_.parameters[j].from_unit(a[j])) / (b[j] - a[j]);
    for (std::size_t k = 0; k < spec_.targets.size(); ++k)
      J(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = (sb[k] - sa[k]) / (b[j] - a[j]) / sigma_obs[k];
  }
  const Eigen::MatrixXd F = J.transpose() * J;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(F);
  res_.sigma.assign(d_, kNaN);
  if (lu.rank() < nd || !F.allFinite()) return;
  const Eigen::MatrixXd cov = lu.inverse();
  for (std::size_t j = 0; j < d_; ++j) {
    const auto jj = static_cast<Eigen::Index>(j);
    res_.sigma[j] = std::sqrt(cov(jj, jj)) * std::abs(dxdu[j]);
  }
}

}  // namespace

double map_points(const Spec& spec) {
  const double d = static_cast<double>(spec.parameters.size());
  return std::pow(spec.grid_points, d) + spec.refine_rounds * std::pow(spec.refine_points, d);
}

Result calibrate(const Spec& spec, const Evaluator& evaluate) { return Calibrator(spec, evaluate).run(); }

}  // namespace agglo::calibrate
