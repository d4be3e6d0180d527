#include "agglo/sectional/stepper.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::sectional {

namespace {
// phi1 = (1 - e^(-x)) / x * h and phi2 = (e^(-x) - 1 + x) / x^2 * h for x = c h >= 0.
double phi1(double x, double h) { return x < 1e-8 ? h * (1.0 - 0.5 * x) : -std::expm1(-x) / x * h; }
double phi2(double x, double h) {
  if (x < 1e-3) return h * (0.5 - x / 6.0 + x * x / 24.0);
  return (std::expm1(-x) + x) / (x * x) * h;
}
}  // namespace

void Etd2Stepper::step(const std::vector<double>& n, double h, std::vector<double>& out) {
  const std::size_t m = n.size();
  coag_.rates(n, birth_, c_);  // held loss rates c; F(N_n) = B(N_n)
  f0_ = birth_;
  a_.resize(m);
  for (std::size_t i = 0; i < m; ++i) a_[i] = n[i] * std::exp(-c_[i] * h) + f0_[i] * phi1(c_[i] * h, h);
  coag_.rates(a_, birth_, fa_);
  out.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    const double fa = birth_[i] - (fa_[i] - c_[i]) * a_[i];
    out[i] = std::max(0.0, a_[i] + (fa - f0_[i]) * phi2(c_[i] * h, h));
  }
}

double Etd2Stepper::trial(const std::vector<double>& n, double h, std::vector<double>& out) {
  step(n, h, full_);
  step(n, 0.5 * h, half_);
  step(half_, 0.5 * h, out);
  double en = 0.0, ev = 0.0, tn = 0.0, tv = 0.0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const double d = out[i] - full_[i];
    en += std::abs(d);
    ev += x_[i] * std::abs(d);
    tn += out[i];
    tv += x_[i] * out[i];
    out[i] = std::max(0.0, out[i] + d / 3.0);
  }
  return std::max(tn > 0.0 ? en / tn : 0.0, tv > 0.0 ? ev / tv : 0.0);
}

double Etd2Stepper::first_step(const std::vector<double>& n) {
  coag_.rates(n, birth_, c_);
  double total = 0.0, rate = 0.0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    total += n[i];
    rate += std::abs(birth_[i] - c_[i] * n[i]);
  }
  return rate > 0.0 ? 1e-3 * total / rate : 0.0;
}

void Etd2Stepper::advance(std::vector<double>& n, double t, double t_end) {
  std::vector<double> next;
  if (h_ <= 0.0) h_ = first_step(n);
  if (h_ <= 0.0) h_ = t_end - t;
  while (t < t_end) {
    const double h = std::min(h_, t_end - t);
    const double err = trial(n, h, next);
    if (!std::isfinite(err)) throw NumericalError(fmt::format("sectional: non-finite state at t = {:.6g} s", t));
    const double grow = err > 0.0 ? std::clamp(0.9 * std::cbrt(tol_ / err), 0.2, 2.0) : 2.0;
    if (err > tol_) {
      ++stats_.rejected;
      h_ = h * grow;
      if (h_ < 1e-12 * (t_end - t))
        throw NumericalError(fmt::format("sectional: time step {:.3g} s too small at t = {:.6g} s", h_, t));
      continue;
    }
    stats_.h_min = stats_.accepted ? std::min(stats_.h_min, h) : h;
    stats_.h_max = std::max(stats_.h_max, h);
    ++stats_.accepted;
    if (h == h_) h_ *= grow;
    t = (h == t_end - t) ? t_end : t + h;
    n.swap(next);
  }
}

}  // namespace agglo::sectional
