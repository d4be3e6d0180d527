#include "agglo/impact/electrostatic_coupling.hpp"

#include "agglo/impact/experiment.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>

#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/electrostatics/coulomb_solver.hpp"
#include "agglo/electrostatics/keys.hpp"

namespace agglo::impact {

namespace {

// Error-controlled re-solves (electrostatic_coupling.hpp): the motion threshold starts small, since
// nothing is known of the hold error before the first measurement, and doubles at most per solve.
constexpr double kStartFraction = 1e-4;
constexpr double kMinFraction = 1e-5;
// The threshold is rescaled towards an error of kAim x tol, growing at most kGrowth x per solve: the
// error is largest at the solve only while the motion does not turn back within an interval, which
// the margin covers (tests/impact/test_coupling.cpp, Coupling.ErrorControlled...).
constexpr double kAim = 0.5;
constexpr double kGrowth = 1.5;

// What to change when the particles of a step overlap beyond the electrostatic regularisation. The
// applied field is named when it dominates: its force scale on a particle, |q| E plus the attraction of
// the dipoles it induces in touching spheres (~ 4 pi eps0 kappa_0 r^2 E^2), exceeds the largest Coulomb
// force between two of the charges at contact, q_i q_k / (4 pi eps0 kappa_0 (r_i + r_k)^2).
std::string overlap_advice(const dem::Particles& p, const es::EsConfig& es) {
  const auto& keys = es::solver_keys();
  const double E = norm(es.external_field);
  const double k = 4.0 * constants::pi * constants::eps0 * es.medium_permittivity;
  double field = 0.0, charges = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    field = std::max(field, std::abs(p.q[i]) * E + k * p.r[i] * p.r[i] * E * E);
    for (std::size_t j = i + 1; j < p.size(); ++j)
      charges = std::max(charges, std::abs(p.q[i] * p.q[j]) / (k * (p.r[i] + p.r[j]) * (p.r[i] + p.r[j])));
  }
  if (E > 0.0 && field > charges)
    return fmt::format("the applied field {} (|E| = {:.3g} V/m) dominates: its force on a particle, up to {:.3g} N, "
                       "exceeds the largest force between the charges, {:.3g} N; lower the field, or raise {}",
                       keys.external_field.dotted(), E, field, charges, keys.min_gap.dotted());
  return fmt::format("raise {} or lower the impact speed", keys.min_gap.dotted());
}

// The extrapolated hold's value w of the way past the last solution v1 along the line from v0.
template <class T>
T along(const T& v1, const T& v0, double w) {
  return v1 + w * (v1 - v0);
}

}  // namespace

ElectrostaticForce::ElectrostaticForce(const CouplingSettings& s)
    : s_(s),
      solver_(es::make_solver(s.es.options)),
      extrapolate_(s.es.hold == "extrapolated"),
      fraction_(s.es.force_tolerance > 0.0 ? kStartFraction : s.es.update_fraction) {}

void ElectrostaticForce::make_fast_path() {
  es::SolverOptions o = s_.es.options;
  o.solver = es::kCoulombSolver;
  coulomb_ = es::make_solver(o);
}

bool ElectrostaticForce::needs_solve(const dem::Particles& p, long step) const {
  if (x_at_solve_.size() != p.size() || step_at_solve_ < 0) return true;
  if (s_.es.update_interval > 0 && step - step_at_solve_ >= s_.es.update_interval) return true;
  const double shrink = es::electrostatic_radius(1.0, s_.es.min_gap);
  for (std::size_t a = 0; a < visible_.size(); ++a)
    for (std::size_t b = a + 1; b < visible_.size(); ++b) {
      const std::size_t i = visible_[a], j = visible_[b];
      Vec3 now = p.x[j] - p.x[i];
      Vec3 then = x_at_solve_[j] - x_at_solve_[i];
      double gap = norm(now) - shrink * (p.r[i] + p.r[j]);
      if (norm(now - then) > fraction_ * gap) return true;
    }
  for (const auto& w : s_.grounded)  // a sphere and its image: separation 2 h along the normal
    for (std::size_t i : visible_) {
      const double h = w.height(p.x[i]);
      const double gap = 2.0 * h - 2.0 * shrink * p.r[i];
      if (2.0 * std::abs(h - w.height(x_at_solve_[i])) > fraction_ * gap) return true;
    }
  return false;
}

void ElectrostaticForce::solve(const dem::Particles& p, long step) {
  // The extrapolated hold keeps the solve before this one (same visible particles only).
  std::swap(was_visible_, visible_);
  // Uncharged particles with kappa_p = kappa_0 are electrostatically invisible: leave them out.
  visible_.clear();
  for (std::size_t k = 0; k < p.size(); ++k)
    if (p.q[k] != 0.0 || p.kappa[k] != s_.es.medium_permittivity) visible_.push_back(k);
  // The visible spheres and their mirror images, in scratch arrays kept between solves (no allocation).
  const std::size_t n_real = visible_.size(), n_all = n_real * (1 + s_.grounded.size());
  std::vector<Vec3>& x = solve_x_;
  std::vector<double>& radius = solve_r_;
  std::vector<double>& q = solve_q_;
  std::vector<double>& kappa = solve_kappa_;
  x.resize(n_all);
  radius.resize(n_all);
  q.resize(n_all);
  kappa.resize(n_all);
  for (std::size_t a = 0; a < n_real; ++a) {
    const std::size_t k = visible_[a];
    x[a] = p.x[k];
    radius[a] = p.r[k];
    q[a] = p.q[k];
    kappa[a] = p.kappa[k];
  }
  std::size_t m = n_real;
  for (const auto& w : s_.grounded)  // mirror spheres (electrostatic_coupling.hpp)
    for (std::size_t a = 0; a < n_real; ++a, ++m) {
      x[m] = x[a] - 2.0 * w.height(x[a]) * w.normal;
      radius[m] = radius[a];
      q[m] = -q[a];
      kappa[m] = kappa[a];
    }
  es::Problem& prob = solve_problem_;
  try {
    es::fill_problem(s_.es, x, radius, q, kappa, prob);
  } catch (const NumericalError& e) {
    throw NumericalError(fmt::format("step {}: {} (particle numbers among the charged/dielectric ones; {})", step,
                                     e.what(), overlap_advice(p, s_.es)));
  }
  auto t0 = std::chrono::steady_clock::now();
  bool uniform = true;
  for (double k : kappa) uniform = uniform && k == s_.es.medium_permittivity;
  if (uniform && !coulomb_) make_fast_path();
  es::Solution& sub = solve_out_;
  sub.energy = 0.0;
  sub.stats = {};
  if (prob.spheres.empty()) {
    sub.force.clear();
    sub.torque.clear();
  } else if (uniform) {
    sub.energy = es::coulomb_forces(prob, sub.force, sub.torque);  // checked by fill_problem: no allocation
  } else {
    sub = solver_->solve(prob);
  }
  keep_previous(was_visible_ == visible_, step);
  last_.energy = sub.energy;
  last_.stats = std::move(sub.stats);
  if (!s_.grounded.empty()) last_.energy *= 0.5;  // the real half of the mirrored system
  last_.force.resize(p.size());
  last_.torque.resize(p.size());
  std::fill(last_.force.begin(), last_.force.end(), Vec3{});
  std::fill(last_.torque.begin(), last_.torque.end(), Vec3{});
  for (std::size_t a = 0; a < visible_.size(); ++a) {
    last_.force[visible_[a]] = sub.force[a];
    last_.torque[visible_[a]] = sub.torque[a];
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (std::size_t k = 0; k < p.size(); ++k)
    if (!isfinite(last_.force[k]) || !isfinite(last_.torque[k]))
      throw NumericalError(fmt::format("electrostatics: non-finite force on particle {} at step {}", k, step));
  energy_ = last_.energy;
  correct_ = !uniform && s_.es.hold == "pair_corrected";
  if (correct_) pair_terms(p, f_s_, u_s_, n_s_);
  x_at_solve_ = p.x;
  step_at_solve_ = step;
  ++solves_;
}

void ElectrostaticForce::add_forces(const dem::Particles& p, long step, double, std::vector<Vec3>& force,
                                    std::vector<Vec3>& torque) {
  const bool fresh = needs_solve(p, step);
  if (fresh && s_.es.force_tolerance > 0.0 && step_at_solve_ >= 0 && x_at_solve_.size() == p.size()) {
    const std::vector<Vec3> held = held_forces(p, step);
    solve(p, step);
    adapt(held);
  } else if (fresh) {
    solve(p, step);
  }
  step_now_ = step;
  const double w = ramp(step);
  if (w != 0.0) {
    for (std::size_t k = 0; k < p.size(); ++k) {
      force[k] += s_.force_scale * along(last_.force[k], prev_force_[k], w);
      torque[k] += s_.force_scale * along(last_.torque[k], prev_torque_[k], w);
    }
    energy_ = along(last_.energy, prev_energy_, w);
    return;
  }
  for (std::size_t k = 0; k < p.size(); ++k) {
    force[k] += s_.force_scale * last_.force[k];
    torque[k] += s_.force_scale * last_.torque[k];
  }
  energy_ = last_.energy;
  if (!correct_ || fresh) return;
  pair_terms(p, f_now_, u_now_, n_now_);
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j, ++k) {
      Vec3 df = s_.force_scale * (f_now_[k] * n_now_[k] - f_s_[k] * n_s_[k]);  // change of the force on j
      force[j] += df;
      force[i] -= df;
      energy_ += u_now_[k] - u_s_[k];
    }
}

// The extrapolated hold's line: the solution about to be replaced becomes its first point.
void ElectrostaticForce::keep_previous(bool same_particles, long step) {
  if (!extrapolate_ || !same_particles || step_at_solve_ < 0 || step <= step_at_solve_) {
    step_at_prev_ = -1;
    return;
  }
  std::swap(prev_force_, last_.force);
  std::swap(prev_torque_, last_.torque);
  prev_energy_ = last_.energy;
  step_at_prev_ = step_at_solve_;
}

// Never beyond the span of the line itself (w <= 1): the held force stays within F_1 + (F_1 - F_0) when an
// interval grows longer than the one before it.
double ElectrostaticForce::ramp(long step) const {
  if (step_at_prev_ < 0 || step <= step_at_solve_) return 0.0;
  return std::min(1.0, double(step - step_at_solve_) / double(step_at_solve_ - step_at_prev_));
}

std::vector<Vec3> ElectrostaticForce::held_forces(const dem::Particles& p, long step) {
  std::vector<Vec3> f = last_.force;
  if (const double w = ramp(step); w != 0.0)
    for (std::size_t k = 0; k < f.size(); ++k) f[k] = along(last_.force[k], prev_force_[k], w);
  if (!correct_) return f;
  pair_terms(p, f_now_, u_now_, n_now_);
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j, ++k) {
      const Vec3 df = f_now_[k] * n_now_[k] - f_s_[k] * n_s_[k];
      f[j] += df;
      f[i] -= df;
    }
  return f;
}

std::vector<Vec3> ElectrostaticForce::applied_forces(const dem::Particles& p) {
  std::vector<Vec3> f = held_forces(p, step_now_);
  for (auto& fk : f) fk *= s_.force_scale;
  return f;
}

void ElectrostaticForce::adapt(const std::vector<Vec3>& held) {
  double fmax = 0.0, emax = 0.0;
  for (std::size_t k = 0; k < held.size(); ++k) {
    fmax = std::max(fmax, norm(last_.force[k]));
    emax = std::max(emax, norm(last_.force[k] - held[k]));
  }
  if (!(fmax > 0.0)) return;
  const double e = emax / fmax, tol = s_.es.force_tolerance;
  ++hold_error_.measured;
  hold_error_.max = std::max(hold_error_.max, e);
  hold_error_.sum += e;
  // The held error grows as the motion (constant hold) or its square (extrapolated hold).
  double factor = kGrowth;
  if (e > 0.0) factor = std::clamp(extrapolate_ ? std::sqrt(kAim * tol / e) : kAim * tol / e, 0.25, kGrowth);
  fraction_ = std::clamp(fraction_ * factor, kMinFraction, 1.0);
  hold_error_.fraction = fraction_;
}

const PairTable& ElectrostaticForce::table_for(const dem::Particles& p, std::size_t i, std::size_t j) {
  const double shrink = es::electrostatic_radius(1.0, s_.es.min_gap);
  PairKey key{p.r[i] * shrink, p.r[j] * shrink, p.kappa[i], p.kappa[j], s_.es.medium_permittivity};
  auto it = tables_.find(key);
  if (it == tables_.end()) {
    double rmin = std::min(key.ri, key.rj);
    double h_min = 0.1 * std::max(s_.es.min_gap, 1e-3) * rmin;
    it = tables_.emplace(key, pair_table(s_.es.options, key, h_min, 50.0 * rmin)).first;
  }
  return *it->second;
}

void ElectrostaticForce::pair_terms(const dem::Particles& p, std::vector<double>& f, std::vector<double>& u,
                                    std::vector<Vec3>& n) {
  const std::size_t np = p.size() * (p.size() - 1) / 2;
  f.assign(np, 0.0);
  u.assign(np, 0.0);
  n.assign(np, Vec3{});
  const double shrink = es::electrostatic_radius(1.0, s_.es.min_gap);
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j, ++k) {
      if (p.q[i] == 0.0 && p.q[j] == 0.0) continue;
      Vec3 d = p.x[j] - p.x[i];
      double dist = norm(d);
      n[k] = d / dist;
      double h = dist - shrink * (p.r[i] + p.r[j]);
      table_for(p, i, j).eval(h, p.q[i], p.q[j], f[k], u[k]);
    }
}

std::unique_ptr<dem::ExternalForce> make_electrostatic_force(const ImpactCase& c) {
  return std::make_unique<ElectrostaticForce>(c.coupling);
}

}  // namespace agglo::impact
