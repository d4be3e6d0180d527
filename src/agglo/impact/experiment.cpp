#include "agglo/impact/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"
#include "agglo/core/constants.hpp"

namespace agglo::impact {

double radius_of_gyration(const dem::Particles& p, std::size_t n) {
  if (n == 0 || n > p.size()) n = p.size();
  Vec3 c;
  for (std::size_t k = 0; k < n; ++k) c += p.x[k];
  c /= static_cast<double>(n);
  double s = 0.0;
  for (std::size_t k = 0; k < n; ++k) s += norm2(p.x[k] - c);
  return std::sqrt(s / static_cast<double>(n));
}

namespace {

std::vector<std::vector<int>> components(const dem::DemSystem& sys) {
  const int n = static_cast<int>(sys.particles().size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (const auto& pr : sys.pairs())
    if (pr.state.active) parent[find(static_cast<int>(pr.i))] = find(static_cast<int>(pr.j));
  std::vector<std::vector<int>> groups;
  std::vector<int> slot(n, -1);
  for (int k = 0; k < n; ++k) {
    int r = find(k);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[slot[r]].push_back(k);
  }
  return groups;
}

io::ParticleSnapshot snapshot(const dem::DemSystem& sys) {
  const auto& p = sys.particles();
  return io::ParticleSnapshot{p.x, p.v, p.w, p.r, p.q, sys.contacts_per_particle()};
}

// Adds the likely input cause to a DEM blow-up message.
[[noreturn]] void rethrow_with_cause(const dem::DemInstability& e) {
  const auto& k = impact_keys();
  throw dem::DemInstability(fmt::format("{}; likely input cause: {} too large for the contact stiffness, or an extreme "
                                        "{}, {} or {}",
                                        e.what(), k.time.dt.dotted(), k.material.density.dotted(),
                                        k.agglomerate.radius.dotted(), k.projectile.radius.dotted()));
}

// Broken, every fragment escaping, and every fragment's surfaces at least `min_gap` from the rest
// (beyond adhesive reach; its kinetic energy already exceeds its electrostatic binding).
bool clearly_broken(const dem::DemSystem& sys, std::size_t n_agg, double kappa0, double min_gap) {
  auto cl = classify(sys, n_agg, kappa0);
  if (!cl.broken) return false;
  const auto& p = sys.particles();
  for (const auto& f : cl.fragments) {
    std::vector<char> in(p.size(), 0);
    for (int k : f.members) in[k] = 1;
    for (std::size_t a = 0; a < p.size(); ++a)
      for (std::size_t b = 0; b < p.size(); ++b)
        if (in[a] && !in[b] && norm(p.x[a] - p.x[b]) - p.r[a] - p.r[b] < min_gap) return false;
  }
  return true;
}

dem::Particles relax(const ImpactCase& c) {
  dem::DemSystem sys(build_agglomerate(c), c.dem);
  if (!c.electrostatics || c.time.relax_time <= 0.0) return sys.particles();
  auto es = make_electrostatic_force(c);
  sys.set_external_force(es.get());
  auto jkr = sys.jkr_for(0, 1);
  const double ke_tol = c.time.relax_energy * jkr.Fc * jkr.deltaC;
  const long max_steps = static_cast<long>(c.time.relax_time / sys.dt());
  for (long s = 0; s < max_steps; ++s) {
    sys.step();
    if (s > 100 && s % 50 == 0 && sys.kinetic_energy() < ke_tol) break;
  }
  sys.check_state();
  dem::Particles p = sys.particles();
  for (auto& v : p.v) v = {};
  for (auto& w : p.w) w = {};
  return p;
}

}  // namespace

ImpactOutcome classify(const dem::DemSystem& sys, std::size_t n_agg, double kappa0) {
  ImpactOutcome out;
  const auto& p = sys.particles();
  out.components = components(sys);
  // The component holding most original particles is the main body; others holding originals are fragments.
  auto originals = [&](const std::vector<int>& g) {
    return std::count_if(g.begin(), g.end(), [&](int k) { return static_cast<std::size_t>(k) < n_agg; });
  };
  std::size_t main = 0;
  for (std::size_t g = 1; g < out.components.size(); ++g)
    if (originals(out.components[g]) > originals(out.components[main])) main = g;
  bool all_escaping = true;
  for (std::size_t g = 0; g < out.components.size(); ++g) {
    if (g == main || originals(out.components[g]) == 0) continue;
    Fragment f;
    f.members = out.components[g];
    std::vector<char> in(p.size(), 0);
    for (int k : f.members) in[k] = 1;
    double mf = 0, mr = 0;
    Vec3 xf, xr, vf, vr;
    for (std::size_t k = 0; k < p.size(); ++k) {
      (in[k] ? mf : mr) += p.m[k];
      (in[k] ? xf : xr) += p.m[k] * p.x[k];
      (in[k] ? vf : vr) += p.m[k] * p.v[k];
    }
    xf /= mf, xr /= mr, vf /= mf, vr /= mr;
    Vec3 dx = xf - xr, dv = vf - vr;
    f.separation_rate = dot(dx, dv) / norm(dx);
    f.relative_ke = 0.5 * mf * mr / (mf + mr) * norm2(dv);
    double u = 0.0;
    for (std::size_t a = 0; a < p.size(); ++a)
      for (std::size_t b = 0; b < p.size(); ++b)
        if (in[a] && !in[b] && p.q[a] != 0.0 && p.q[b] != 0.0)
          u += p.q[a] * p.q[b] / (4.0 * constants::pi * constants::eps0 * kappa0 * norm(p.x[a] - p.x[b]));
    f.binding = std::max(0.0, -u);
    f.escaping = f.separation_rate > 0.0 && f.relative_ke > f.binding;
    all_escaping = all_escaping && f.escaping;
    out.fragments.push_back(f);
  }
  const bool split = !out.fragments.empty();
  out.broken = split && all_escaping;
  out.undecided = split && !all_escaping;
  return out;
}

dem::Particles relaxed_agglomerate(const ImpactCase& c) {
  try {
    return relax(c);
  } catch (const dem::DemInstability& e) {
    rethrow_with_cause(e);
  }
}

namespace {

// Energy watchdog bound (docs/dem.md, "Limits and checks"): kinetic + electrostatic energy may exceed
// its launch value by at most half the launch energy scale plus kJkrReleasePerParticle F_C delta_C
// per particle, the most the JKR contacts can release (about 1.5 F_C delta_C per broken contact, at
// most 6 contacts per particle) with margin. Any larger rise is energy made by the integrator.
constexpr double kJkrReleasePerParticle = 10.0;

// One run from the launch of the projectile to the classification, in phases: launch (constructor),
// approach until the projectile first touches, contact phase (after_contact, extended while the
// outcome is undecided), result. Every step is recorded (time series, snapshots) on the output clock.
class ImpactRun {
 public:
  ImpactRun(const ImpactCase& c, dem::Particles agglomerate, double speed, Recorder* rec, const ProgressFn& progress)
      : c_(c), speed_(speed), sys_(std::move(agglomerate), c.dem), n_agg_(sys_.particles().size()), rec_(rec),
        progress_(progress) {
    if (c.electrostatics) {
      es_ = make_electrostatic_force(c);
      sys_.set_external_force(es_.get());
    }
    const double rp = c.agglomerate.radius;
    const double sigma = c.agglomerate.charge_density;
    u0_ = 2.0 * constants::pi * rp * rp * rp * sigma * sigma / constants::eps0;
    kappa0_ = es_ ? c.medium_permittivity : 1.0;
    t_launch_ = sys_.time();
    dem::Particles tmp = sys_.particles();
    add_projectile(tmp, c, speed);
    sys_.add_particle(tmp.x.back(), tmp.r.back(), c.agglomerate.density, tmp.v.back(), tmp.q.back(), tmp.kappa.back());
  }

  ImpactOutcome run() {
    ImpactOutcome out;
    out.speed = speed_;
    out.dt = sys_.dt();
    try {
      sys_.compute_forces();  // contacts and electrostatic energy of the launch state
      arm_watchdog();
      record();
      out.contact = approach();
      guard();
      out.t_contact = since_launch();
      if (out.contact) contact_phase(out);
      guard();
    } catch (const dem::DemInstability& e) {
      rethrow_with_cause(e);
    }
    out.t_end = since_launch();
    if (auto* ef = dynamic_cast<ElectrostaticForce*>(es_.get())) {
      out.es_solves = ef->solves();
      out.es_seconds = ef->seconds();
    }
    out.steps = sys_.steps();
    return out;
  }

 private:
  double since_launch() const { return sys_.time() - t_launch_; }

  void step() {
    sys_.step();
    if (sys_.steps() % 256 == 0) check_energy();
    record();
  }

  // The state is finite and sane and the energy has not risen beyond the watchdog bound.
  void guard() const {
    sys_.check_state();
    check_energy();
  }

  double watched_energy() const { return sys_.kinetic_energy() + sys_.external_energy(); }

  void arm_watchdog() {
    const auto& p = sys_.particles();
    const std::size_t big = static_cast<std::size_t>(std::max_element(p.r.begin(), p.r.end()) - p.r.begin());
    const auto jkr = sys_.jkr_for(static_cast<std::uint32_t>(big), static_cast<std::uint32_t>(big));
    e_launch_ = watched_energy();
    e_allowed_ = 0.5 * (sys_.kinetic_energy() + std::abs(sys_.external_energy())) +
                 kJkrReleasePerParticle * jkr.Fc * jkr.deltaC * static_cast<double>(p.size());
  }

  void check_energy() const {
    const double e = watched_energy();
    if (e <= e_launch_ + e_allowed_) return;
    const auto& p = sys_.particles();
    std::size_t fast = 0;
    for (std::size_t q = 1; q < p.size(); ++q)
      if (!(norm2(p.v[q]) <= norm2(p.v[fast]))) fast = q;
    throw dem::DemInstability(fmt::format("DEM: energy rise at step {} (t = {:.6g} s): kinetic + electrostatic "
                                          "energy {:.3g} J exceeds its launch value {:.3g} J by more than {:.3g} J "
                                          "(fastest particle {}, |v| = {:.3g} m/s)",
                                          sys_.steps(), sys_.time(), e, e_launch_, e_allowed_, fast,
                                          norm(p.v[fast])));
  }

  // Until the projectile (the last particle) is in contact; false if max_approach passes first.
  bool approach() {
    const double rp = c_.agglomerate.radius;
    const double gap = c_.projectile.gap_radii * rp;
    const double max_approach =
        c_.time.max_approach > 0.0 ? c_.time.max_approach : 5.0 * (gap + rp) / std::max(speed_, 1e-3) + 1e-4;
    while (since_launch() < max_approach) {
      step();
      if (progress_ && sys_.steps() % 2000 == 0) progress_(0.0, since_launch());
      if (projectile_touches()) return true;
    }
    return false;
  }

  bool projectile_touches() const {
    for (const auto& pr : sys_.pairs())
      if (pr.state.active && (pr.i == n_agg_ || pr.j == n_agg_)) return true;
    return false;
  }

  // after_contact, then extensions while undecided; classifies the end state.
  void contact_phase(ImpactOutcome& out) {
    double t_stop = sys_.time() + c_.time.after_contact;
    for (int ext = 0;; ++ext) {
      out.early_stop = run_until(t_stop);
      guard();
      auto cl = classify(sys_, n_agg_, kappa0_);
      out.broken = cl.broken;
      out.undecided = cl.undecided;
      out.components = cl.components;
      out.fragments = cl.fragments;
      out.extensions = ext;
      if (!cl.undecided || ext >= c_.time.max_extensions) break;
      t_stop += c_.time.extension;
    }
  }

  // Integrates to t_stop; true if stopped before because the agglomerate is clearly broken.
  bool run_until(double t_stop) {
    const double t_from = sys_.time();
    const double min_gap = c_.time.early_stop_gap * c_.agglomerate.radius;
    while (sys_.time() < t_stop) {
      step();
      if (progress_ && sys_.steps() % 2000 == 0)
        progress_((sys_.time() - t_from) / (t_stop - t_from), since_launch());
      if (c_.time.early_stop && sys_.steps() % 500 == 0 && clearly_broken(sys_, n_agg_, kappa0_, min_gap)) return true;
    }
    return false;
  }

  void record() {
    if (!rec_) return;
    const double t = since_launch();
    const bool row_due = t + 1e-15 >= next_row_;
    const bool snap_due = c_.output.snapshot_interval > 0.0 && t + 1e-15 >= next_snap_;
    if (row_due || snap_due) guard();
    if (row_due) {
      const double ues = sys_.external_energy();
      rec_->rows.push_back({t, sys_.kinetic_energy(), ues, u0_ > 0 ? ues / u0_ : 0.0,
                            radius_of_gyration(sys_.particles()), radius_of_gyration(sys_.particles(), n_agg_),
                            sys_.active_contacts()});
      next_row_ += c_.output.timeseries_interval;
    }
    if (snap_due) {
      rec_->snapshots.emplace_back(t, snapshot(sys_));
      next_snap_ += c_.output.snapshot_interval;
    }
  }

  const ImpactCase& c_;
  double speed_;  // launch speed of the projectile [m/s]
  dem::DemSystem sys_;
  std::size_t n_agg_;  // the projectile is particle n_agg_
  Recorder* rec_;
  const ProgressFn& progress_;
  std::unique_ptr<dem::ExternalForce> es_;
  double u0_ = 0.0;      // U0 = 2 pi r_p^3 sigma_f^2 / eps0 [J]
  double kappa0_ = 1.0;  // medium permittivity of the point-charge binding
  double t_launch_ = 0.0;
  double next_row_ = 0.0, next_snap_ = 0.0;
  double e_launch_ = 0.0;   // kinetic + electrostatic energy at launch [J]
  double e_allowed_ = 0.0;  // largest rise above it the watchdog accepts [J]
};

}  // namespace

ImpactOutcome run_impact(const ImpactCase& c, double speed, Recorder* rec, const ProgressFn& progress,
                         const dem::Particles* relaxed) {
  ImpactRun run(c, relaxed ? *relaxed : relaxed_agglomerate(c), speed, rec, progress);
  return run.run();
}

}  // namespace agglo::impact
