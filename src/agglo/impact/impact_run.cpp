// One collision run in phases (impact_run.hpp).
#include "agglo/impact/impact_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"
#include "agglo/impact/estimate.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/intact.hpp"

namespace agglo::impact {

namespace {

// Energy watchdog bound (docs/dem.md, "Limits and checks"): kinetic + electrostatic energy may exceed
// its launch value by at most half the launch energy scale plus kJkrReleasePerParticle F_C delta_C
// per particle, the most the JKR contacts can release (about 1.5 F_C delta_C per broken contact, at
// most 6 contacts per particle) with margin. Any larger rise is energy made by the integrator.
constexpr double kJkrReleasePerParticle = 10.0;

dem::ParticleSnapshot snapshot(const dem::DemSystem& sys) {
  const auto& p = sys.particles();
  return dem::ParticleSnapshot{p.x, p.v, p.w, p.r, p.q, sys.contacts_per_particle()};
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

// Smallest surface gap between a particle and a wall [m].
double wall_gap(const dem::DemSystem& sys) {
  const auto& p = sys.particles();
  double gap = std::numeric_limits<double>::infinity();
  for (const auto& w : sys.params().walls)
    for (std::size_t q = 0; q < p.size(); ++q) gap = std::min(gap, w.height(p.x[q]) - p.r[q]);
  return std::max(gap, 0.0);
}

}  // namespace

dem::DemParams run_params(const ImpactCase& c) {
  dem::DemParams d = c.dem;
  d.dt = time_step(c);
  return d;
}

ImpactRun::ImpactRun(const ImpactCase& c, dem::Particles agglomerate, double speed, Recorder* rec,
                     ProgressFn progress)
    : c_(c), speed_(speed), sys_(std::move(agglomerate), run_params(c)), n_agg_(sys_.particles().size()), rec_(rec),
      progress_(std::move(progress)) {
  if (c.electrostatics) {
    es_ = make_electrostatic_force(c);
    sys_.set_external_force(es_.get());
  }
  const double rp = c.agglomerate.radius;
  const double sigma = c.agglomerate.charge_density;
  // U0 is the seed's scale of the built-in shapes; a list agglomerate has no sigma_f of its own: NaN.
  u0_ = c.agglomerate.shape == "list" ? std::numeric_limits<double>::quiet_NaN()
                                      : 2.0 * constants::pi * rp * rp * rp * sigma * sigma / constants::eps0;
  kappa0_ = es_ ? c.medium_permittivity : 1.0;
  intact_stop_ = c.time.intact_stop == "on" || (c.time.intact_stop == "vcrit" && c.time.bisection);
  set_launch(sys_.particles());
  double gap = c.projectile.gap_radii * rp;
  at_.t_launch = sys_.time();
  if (c.wall_impact) {  // the agglomerate itself moves onto the wall (docs/dem.md "Gas and walls")
    gap = wall_gap(sys_);
    for (auto& v : sys_.particles().v) v = {speed, 0.0, 0.0};
  }
  max_approach_ = c.time.max_approach > 0.0 ? c.time.max_approach : 5.0 * (gap + rp) / std::max(speed, 1e-3) + 1e-4;
  if (c.wall_impact) return;
  dem::Particles tmp = sys_.particles();
  add_projectile(tmp, c, speed);
  relax_projectile(c, tmp, n_agg_, speed);  // an aggregate with charges or in a field, as the target
  for (std::size_t q = n_agg_; q < tmp.size(); ++q)
    sys_.add_particle(tmp.x[q], tmp.r[q], material_density(c, tmp.mat[q]), tmp.v[q], tmp.q[q], tmp.kappa[q], tmp.mat[q]);
}

ImpactRun::~ImpactRun() = default;

ImpactOutcome ImpactRun::run(const BoundaryFn& boundary) {
  try {
    if (at_.phase == ImpactPhase::launch) {
      launch();
      if (approach_) skip_free_flight(*approach_);
    }
    if (boundary) boundary(*this);
    while (at_.phase != ImpactPhase::done) {
      advance();
      if (boundary) boundary(*this);
    }
  } catch (const dem::DemInstability& e) {
    rethrow_with_cause(e);
  }
  return outcome();
}

void ImpactRun::launch() {
  sys_.compute_forces();  // contacts and electrostatic energy of the launch state
  check_one_agglomerate(sys_, n_agg_, "at the launch of the projectile");
  arm_watchdog();
  record();
  at_.phase = ImpactPhase::approach;
}

void ImpactRun::advance() {
  if (at_.phase == ImpactPhase::approach) approach_step();
  else if (at_.phase == ImpactPhase::contact) contact_step();
}

// One step of the approach (until the projectile, the last particle, is in contact; no contact if
// max_approach passes first).
void ImpactRun::approach_step() {
  if (!(since_launch() < max_approach_)) return end_approach(false);
  step();
  if (progress_ && sys_.steps() % 2000 == 0) progress_(0.0, since_launch());
  if (projectile_touches()) end_approach(true);
}

void ImpactRun::end_approach(bool touched) {
  guard();
  at_.contact = touched;
  at_.t_contact = since_launch();
  if (!touched) {
    if (!c_.miss_is_outcome) missed();
    at_.phase = ImpactPhase::done;  // no contact: nothing to integrate further (ImpactCase::miss_is_outcome)
    return;
  }
  at_.phase = ImpactPhase::contact;
  at_.extensions = 0;
  at_.t_from = sys_.time();
  at_.t_stop = sys_.time() + c_.time.after_contact;
}

// One step of a contact segment (after_contact, then each extension); the segment ends at t_stop or
// early when the agglomerate is clearly broken or (time.intact_stop) provably intact for good.
void ImpactRun::contact_step() {
  if (!(sys_.time() < at_.t_stop)) return end_segment(false);
  step();
  if (progress_ && sys_.steps() % 2000 == 0)
    progress_((sys_.time() - at_.t_from) / (at_.t_stop - at_.t_from), since_launch());
  if (sys_.steps() % 500 != 0) return;
  const double min_gap = c_.time.early_stop_gap * c_.agglomerate.radius;
  if ((c_.time.early_stop && clearly_broken(sys_, n_agg_, kappa0_, min_gap)) || (intact_stop_ && intact_for_good()))
    end_segment(true);
}

bool ImpactRun::intact_for_good() {
  auto* ef = dynamic_cast<ElectrostaticForce*>(es_.get());
  if (!ef) return intact_bound(sys_, n_agg_, nullptr, kappa0_).intact();
  const std::vector<Vec3> f = ef->applied_forces(sys_.particles());
  return intact_bound(sys_, n_agg_, &f, kappa0_).intact();
}

// Classifies the end of a segment: done unless undecided with extensions left.
void ImpactRun::end_segment(bool early) {
  at_.early_stop = early;
  guard();
  const auto cl = classify(sys_, n_agg_, kappa0_);
  if (!cl.undecided || at_.extensions >= c_.time.max_extensions) {
    at_.phase = ImpactPhase::done;
    guard();
    return;
  }
  ++at_.extensions;
  at_.t_from = sys_.time();
  at_.t_stop += c_.time.extension;
}

// No contact by the end of the approach: no impact happened, so there is nothing to classify.
void ImpactRun::missed() const {
  const auto& p = sys_.particles();
  const auto& k = impact_keys();
  if (c_.wall_impact)
    throw InvalidRunError(fmt::format("the agglomerate never touched the wall within the approach limit {:.3g} s ({} = "
                                      "{:g}, 0 = 5x the ballistic time): no impact happened; likely cause: {} or {} "
                                      "place the wall out of its path along +x, or {} is too short",
                                      max_approach_, k.time.max_approach.dotted(), c_.time.max_approach,
                                      k.wall.position.dotted(), k.wall.normal.dotted(), k.time.max_approach.dotted()));
  Vec3 c;
  for (std::size_t q = 0; q < n_agg_; ++q) c += p.x[q] / static_cast<double>(n_agg_);
  double reach = 0.0;  // largest distance from the launch line at which the projectile still touches
  for (std::size_t q = 0; q < n_agg_; ++q)
    reach = std::max(reach, std::hypot(p.x[q].y - c.y, p.x[q].z - c.z) + p.r[q] + p.r[n_agg_]);
  const double lateral = std::abs(c_.projectile.offset_radii) * c_.agglomerate.radius;
  std::string cause;
  if (lateral > reach)
    cause = fmt::format("the offset {} = {:g} r_p = {:.3g} m passes beside the agglomerate (it reaches {:.3g} m from "
                        "its centroid across the flight path)",
                        k.projectile.offset_radii.dotted(), c_.projectile.offset_radii, lateral, reach);
  else if (es_)
    cause = "the electrostatic forces (charges or applied field) deflected or stopped the projectile, or moved the "
            "agglomerate away";
  else
    cause = fmt::format("{} is too short for the approach", k.time.max_approach.dotted());
  throw InvalidRunError(fmt::format("the projectile never touched the agglomerate within the approach limit {:.3g} s "
                                    "({} = {:g}, 0 = 5x the ballistic time): no impact happened, so there is no "
                                    "outcome; likely cause: {}",
                                    max_approach_, k.time.max_approach.dotted(), c_.time.max_approach, cause));
}

ImpactOutcome ImpactRun::outcome() const {
  ImpactOutcome out;
  out.speed = speed_;
  out.dt = sys_.dt();
  out.contact = at_.contact;
  out.t_contact = at_.t_contact;
  if (at_.contact) {
    const auto cl = classify(sys_, n_agg_, kappa0_);
    out.broken = cl.broken;
    out.undecided = cl.undecided;
    out.components = cl.components;
    out.fragments = cl.fragments;
    out.extensions = at_.extensions;
    out.early_stop = at_.early_stop;
    out.breakage = breakage();
  }
  out.t_end = since_launch();
  if (auto* ef = dynamic_cast<ElectrostaticForce*>(es_.get())) {
    out.es_solves = ef->solves();
    out.es_seconds = ef->seconds();
    const HoldErrorStats& h = ef->hold_error();
    if (h.measured > 0) out.es_hold_error = {h.measured, h.max, h.sum / double(h.measured), h.fraction};
  }
  out.steps = sys_.steps();
  if (!c_.dem.walls.empty()) out.wall_contacts = sys_.wall_contacts();
  if (c_.miss_is_outcome && sys_.particles().size() == 2) {
    const auto& p = sys_.particles();
    const double mu = p.m[0] * p.m[1] / (p.m[0] + p.m[1]);
    out.pair_energy = 0.5 * mu * norm2(p.v[0] - p.v[1]) +
                      p.q[0] * p.q[1] / (4.0 * constants::pi * constants::eps0 * kappa0_ * norm(p.x[0] - p.x[1]));
  }
  return out;
}

// The agglomerate at the launch and its contacts, from a DEM system of its own (a restored run, whose
// launch state is that of the checkpoint, skips launch()).
void ImpactRun::set_launch(dem::Particles agglomerate) {
  launch_agg_ = std::move(agglomerate);
  dem::DemSystem probe(launch_agg_, c_.dem);
  probe.compute_forces();
  launch_edges_ = contact_edges(probe, n_agg_);
}

// The breakage observables of the current state (breakage.hpp); sticking or rebound for a wall impact.
Breakage ImpactRun::breakage() const {
  const auto& p = sys_.particles();
  const auto edges = contact_edges(sys_, p.size());
  Breakage b = measure_breakage(launch_agg_, launch_edges_, p, edges);
  if (!c_.wall_impact) return b;
  std::vector<char> on_wall(p.size(), 0);
  for (std::size_t k = 0; k < c_.dem.walls.size(); ++k)
    for (std::size_t q = 0; q < p.size(); ++q) on_wall[q] = on_wall[q] || sys_.wall_contacts(k).state[q].active;
  double ke = 0.0;
  for (double m : launch_agg_.m) ke += 0.5 * m * speed_ * speed_;
  measure_rebound(b, p, edges, on_wall, c_.dem.walls.front().normal, ke);
  return b;
}

void ImpactRun::step() {
  sys_.step();
  if (sys_.steps() % 256 == 0) check_energy();
  record();
}

// The state is finite and sane and the energy has not risen beyond the watchdog bound.
void ImpactRun::guard() const {
  sys_.check_state();
  check_energy();
}

double ImpactRun::watched_energy() const { return sys_.kinetic_energy() + sys_.external_energy(); }

void ImpactRun::arm_watchdog() {
  const auto& p = sys_.particles();
  const std::size_t big = static_cast<std::size_t>(std::max_element(p.r.begin(), p.r.end()) - p.r.begin());
  const auto jkr = sys_.jkr_for(static_cast<std::uint32_t>(big), static_cast<std::uint32_t>(big));
  at_.e_launch = watched_energy();
  at_.e_allowed = 0.5 * (sys_.kinetic_energy() + std::abs(sys_.external_energy())) +
               kJkrReleasePerParticle * jkr.Fc * jkr.deltaC * static_cast<double>(p.size());
}

void ImpactRun::check_energy() const {
  const double e = watched_energy();
  if (e <= at_.e_launch + at_.e_allowed) return;
  const auto& p = sys_.particles();
  std::size_t fast = 0;
  for (std::size_t q = 1; q < p.size(); ++q)
    if (!(norm2(p.v[q]) <= norm2(p.v[fast]))) fast = q;
  throw dem::DemInstability(fmt::format("DEM: energy rise at step {} (t = {:.6g} s): kinetic + electrostatic "
                                        "energy {:.3g} J exceeds its launch value {:.3g} J by more than {:.3g} J "
                                        "(fastest particle {}, |v| = {:.3g} m/s)",
                                        sys_.steps(), sys_.time(), e, at_.e_launch, at_.e_allowed, fast,
                                        norm(p.v[fast])));
}

bool ImpactRun::projectile_touches() const {
  if (c_.wall_impact) return sys_.wall_contacts() > 0;
  for (const auto& pr : sys_.pairs())  // a contact between the agglomerate and the projectile's particles
    if (pr.state.active && (pr.i < n_agg_) != (pr.j < n_agg_)) return true;
  return false;
}

void ImpactRun::record() {
  if (!rec_) return;
  const double t = since_launch();
  const bool row_due = t + 1e-15 >= at_.next_row;
  const bool snap_due = c_.output.snapshot_interval > 0.0 && t + 1e-15 >= at_.next_snap;
  if (row_due || snap_due) guard();
  if (row_due) {
    const double ues = sys_.external_energy();
    const double u_rel = std::isnan(u0_) ? u0_ : (u0_ > 0 ? ues / u0_ : 0.0);
    rec_->rows.push_back({t, sys_.kinetic_energy(), ues, u_rel,
                          radius_of_gyration(sys_.particles()), radius_of_gyration(sys_.particles(), n_agg_),
                          sys_.active_contacts()});
    at_.next_row += c_.output.timeseries_interval;
  }
  if (snap_due) {
    rec_->snapshots.emplace_back(t, snapshot(sys_));
    at_.next_snap += c_.output.snapshot_interval;
  }
}

}  // namespace agglo::impact
