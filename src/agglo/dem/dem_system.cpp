#include "agglo/dem/dem_system.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/dem/parallel_for.hpp"

namespace agglo::dem {

namespace {

std::uint32_t material_id(const Particles& p, std::size_t q) { return q < p.mat.size() ? p.mat[q] : 0; }

// Smallest period of the pairs among the particles `idx` (material pairs of `mats`; a table of one
// material serves every particle whatever its material id).
double pair_period(const Particles& p, const std::vector<std::size_t>& idx, const MaterialPairs& mats) {
  const auto id = [&](std::size_t q) { return mats.count > 1 ? material_id(p, q) : 0u; };
  double best = 1e300;
  for (std::size_t a = 0; a < idx.size(); ++a)
    for (std::size_t b = a; b < idx.size(); ++b) {
      auto i = idx[a], j = idx[b];
      const ContactParams& c = mats.at(id(i), id(j));
      double R = p.r[i] * p.r[j] / (p.r[i] + p.r[j]);
      auto jkr = JkrPair::make(R, c.estar(), c.surface_energy);
      double mstar = p.m[i] * p.m[j] / (p.m[i] + p.m[j]);
      double k0 = 0.9905 * jkr.Fc / jkr.deltaC;
      best = std::min(best, 2.0 * constants::pi * std::sqrt(mstar / k0));
    }
  return best;
}

// The three lightest particles (the smallest period belongs to the lightest, smallest particles), then
// the lightest of each further material.
std::vector<std::size_t> period_candidates(const Particles& p, std::size_t materials) {
  std::vector<std::size_t> idx(p.size());
  for (std::size_t k = 0; k < idx.size(); ++k) idx[k] = k;
  std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return p.m[a] < p.m[b]; });
  const std::size_t lim = std::min<std::size_t>(idx.size(), 3);
  std::vector<std::size_t> out(idx.begin(), idx.begin() + lim);
  if (materials <= 1) return out;
  std::vector<bool> seen(materials, false);
  for (std::size_t q : out) seen[material_id(p, q)] = true;
  for (std::size_t q : idx)
    if (!seen[material_id(p, q)]) {
      seen[material_id(p, q)] = true;
      out.push_back(q);
    }
  return out;
}

}  // namespace

double reference_period(const Particles& p, const ContactParams& c) {
  return pair_period(p, period_candidates(p, 1), MaterialPairs(c, {}));
}

double reference_period(const Particles& p, const DemParams& d) {
  const MaterialPairs mats(d.contact, d.materials);
  double best = pair_period(p, period_candidates(p, mats.count), mats);
  if (p.size() == 0) return best;
  // The lightest particle of each material has the shortest wall period (R* = r, m* = m).
  for (std::size_t light : period_candidates(p, mats.count))
    for (const Wall& w : d.walls) {
      const auto jkr = wall_jkr(w, mats, material_id(p, light), p.r[light]);
      const double k0 = 0.9905 * jkr.Fc / jkr.deltaC;
      best = std::min(best, 2.0 * constants::pi * std::sqrt(p.m[light] / k0));
    }
  return best;
}

DemSystem::DemSystem(Particles particles, DemParams params)
    : DemSystem(std::move(particles), params, params.contact.models) {}

DemSystem::DemSystem(Particles particles, DemParams params, const contact::ModelNames& models)
    : p_(std::move(particles)),
      params_(params),
      mats_(params_.contact, params_.materials),
      law_(mats_, models) {
  p_.mat.resize(p_.size(), 0);
  dt_ = params_.dt > 0.0 ? params_.dt : reference_period(p_, params_) / params_.steps_per_period;
  double rmin = p_.size() ? *std::min_element(p_.r.begin(), p_.r.end()) : 1.0;
  skin_ = params_.skin > 0.0 ? params_.skin : 0.1 * rmin;
  attach();
}

JkrPair DemSystem::wall_jkr(std::uint32_t i, const Wall& w) const { return dem::wall_jkr(w, mats_, p_.mat[i], p_.r[i]); }

void DemSystem::attach() {
  const std::size_t n = p_.size();
  const double h = 0.5 * dt_;
  for (std::size_t i = kick_v_.size(); i < n; ++i) {
    kick_v_.push_back(h / p_.m[i]);
    kick_w_.push_back(h / p_.I[i]);
  }
  walls_.resize(params_.walls.size());
  for (std::size_t k = 0; k < walls_.size(); ++k) {
    auto& wc = walls_[k];
    wc.state.resize(n);
    for (std::size_t i = wc.jkr.size(); i < n; ++i)
      wc.jkr.push_back(wall_jkr(static_cast<std::uint32_t>(i), params_.walls[k]));
    for (std::size_t i = wc.kind.size(); i < n; ++i) wc.kind.push_back(wall_kind(params_.walls[k], mats_, p_.mat[i]));
  }
  if (!params_.gas.enabled) return;
  for (std::size_t i = decay_.size(); i < n; ++i) {
    const double tau = params_.gas.relaxation_time(p_.m[i], p_.r[i]);
    const double x = -0.5 * dt_ / tau;
    decay_.push_back(std::exp(x));
    lag_.push_back(-tau * std::expm1(x));
  }
}

void DemSystem::add_wall_and_body_forces() {
  const auto n = static_cast<std::int64_t>(p_.size());
  for (std::size_t k = 0; k < walls_.size(); ++k) {
    if (!reference_) {
      law_.accumulate_wall(params_.walls[k], walls_[k], p_, dt_);
      continue;
    }
    law_.evaluate_wall(params_.walls[k], walls_[k], p_, dt_, wall_forces_);
    parallel_for(n, [&](std::int64_t q) {
      p_.f[q] += wall_forces_[q].f_on_i;
      p_.t[q] += wall_forces_[q].t_on_i;
    });
  }
  const Vec3 g = params_.gravity;
  if (norm2(g) > 0.0) parallel_for(n, [&](std::int64_t q) { p_.f[q] += p_.m[q] * g; });
}

// The arrays of the half kicks and the drift (kick_drift.hpp): kick_v_ = h/m, kick_w_ = h/I (h = dt/2); with
// gas drag the exact relaxation over h towards the gas velocity (gas_drag.hpp); the rebuild test against the
// positions at the last build when `tracked`.
VerletArrays DemSystem::verlet_arrays(bool tracked) {
  VerletArrays a;
  a.x = p_.x.data();
  a.v = p_.v.data();
  a.w = p_.w.data();
  a.f = p_.f.data();
  a.t = p_.t.data();
  a.kick_v = kick_v_.data();
  a.kick_w = kick_w_.data();
  if (params_.gas.enabled) {
    a.decay = decay_.data();
    a.lag = lag_.data();
    a.m = p_.m.data();
    a.u = params_.gas.flow;
  }
  if (tracked) a.x_at_build = nl_.positions_at_build().data();
  a.dt = dt_;
  a.lim2 = 0.25 * skin_ * skin_;
  return a;
}

JkrPair DemSystem::jkr_for(std::uint32_t i, std::uint32_t j) const {
  const ContactParams& c = mats_.at(p_.mat[i], p_.mat[j]);
  double R = p_.r[i] * p_.r[j] / (p_.r[i] + p_.r[j]);
  return JkrPair::make(R, c.estar(), c.surface_energy);
}

void DemSystem::rebuild_list() {
  nl_.build(p_.x, p_.r, skin_, [this](Pair& pr) {
    pr.kind = mats_.kind(p_.mat[pr.i], p_.mat[pr.j]);
    pr.jkr = jkr_for(pr.i, pr.j);
  });
}

void DemSystem::compute_forces(int rebuild) {
  if (rebuild < 0 ? nl_.needs_rebuild(p_.x, skin_) : rebuild == 1) rebuild_list();
  if (reference_)
    gather_pair_forces();
  else if (runs_parallel(static_cast<std::int64_t>(nl_.pairs().size())))
    accumulate_in_blocks();
  else
    law_.accumulate_pairs(nl_.pairs(), p_, dt_);
  if (!walls_.empty() || norm2(params_.gravity) > 0.0) add_wall_and_body_forces();
  if (ext_) ext_->add_forces(p_, step_, time_, p_.f, p_.t);
  forces_ready_ = true;
}

// The blocks of pairs, one per thread (pair_blocks.hpp), made again after every rebuild of the list (and when
// the thread count or the particle count changes).
void DemSystem::ensure_blocks() {
  const auto nb = static_cast<std::size_t>(std::max(1, max_threads()));
  const auto& pairs = nl_.pairs();
  if (blocks_builds_ != nl_.builds() || blocks_.blocks() != nb || blocks_pairs_ != pairs.size() ||
      blocks_.first_particle.back() != p_.size()) {  // (blocks() != nb also when none were made yet)
    blocks_ = contact::make_pair_blocks(pairs, p_.size(), nb);
    blocks_builds_ = nl_.builds();
    blocks_pairs_ = pairs.size();
  }
  pair_forces_.resize(pairs.size());
}

// Inside a parallel region, on every thread of its team: phase 1 (this thread's share of the crossing pairs),
// a barrier, phase 2 of the blocks this thread takes (block b on thread b mod team size).
void DemSystem::pair_phases() {
  const auto tid = static_cast<std::size_t>(thread_id()), nth = static_cast<std::size_t>(team_size());
  law_.crossing_forces(nl_.pairs(), p_, dt_, blocks_, tid, nth, pair_forces_);
#pragma omp barrier
  for (std::size_t b = tid; b < blocks_.blocks(); b += nth) law_.block_forces(nl_.pairs(), p_, dt_, blocks_, b, pair_forces_);
}

// The parallel path: the fast path's sums on blocks of pairs, bit for bit.
void DemSystem::accumulate_in_blocks() {
  ensure_blocks();
#pragma omp parallel num_threads(static_cast<int>(blocks_.blocks()))
  pair_phases();
}

// The fused parallel step (parallel_step): above kParallelThreshold pairs on several threads, for a list built
// for the current particles, without an external force (called between the phases of a step).
bool DemSystem::parallel_step_applies() const {
  return !reference_ && !ext_ && nl_.built_for(p_.size()) &&
         runs_parallel(static_cast<std::int64_t>(nl_.pairs().size()));
}

// step() in one parallel region: each thread kicks and drifts the particles of its blocks and tests them
// against the skin; a barrier (the OR of the threads' flags); a rebuild of the list by one thread when a
// particle moved beyond half the skin; the two phases of the pair blocks (one barrier); the closing kick of
// each block's particles by the thread that summed their forces. With walls or gravity their forces and the
// closing kick follow the region. The same operations per particle and pair as the serial step.
void DemSystem::parallel_step() {
  ensure_blocks();
  const int nt = std::max(1, max_threads());
  far_.assign(static_cast<std::size_t>(nt), ThreadFlag{});
  const bool kick_inside = walls_.empty() && norm2(params_.gravity) == 0.0;
  const VerletArrays a = verlet_arrays(true);
  const auto& first = blocks_.first_particle;
#pragma omp parallel num_threads(nt)
  {
    const auto tid = static_cast<std::size_t>(thread_id()), nth = static_cast<std::size_t>(team_size());
    bool far = false;
    for (std::size_t b = tid; b < blocks_.blocks(); b += nth) far = kick_drift(a, first[b], first[b + 1]) || far;
    far_[tid].far = far;
#pragma omp barrier
    bool any = false;
    for (std::size_t t = 0; t < nth; ++t) any = any || far_[t].far;
    if (any) {
#pragma omp single
      {
        rebuild_list();
        ensure_blocks();
      }
    }
    pair_phases();
    if (kick_inside)
      for (std::size_t b = tid; b < blocks_.blocks(); b += nth) kick(a, first[b], first[b + 1]);
  }
  time_ += dt_;
  ++step_;
  if (kick_inside) return;
  add_wall_and_body_forces();
  closing_kick();
}

// The closing half kick of every particle (the reference twin one particle at a time).
void DemSystem::closing_kick() {
  const VerletArrays a = verlet_arrays(false);
  const auto n = static_cast<std::int64_t>(p_.size());
  if (reference_)
    parallel_for(n, [&](std::int64_t q) { kick_one(a, static_cast<std::size_t>(q)); });
  else
    parallel_for_ranges(n, kVerletChunk, [&](std::int64_t b, std::int64_t e) { kick(a, b, e); });
}

void DemSystem::gather_pair_forces() {
  law_.evaluate_pairs(nl_.pairs(), p_, dt_, pair_forces_);
  const auto& off = nl_.offsets();
  const auto& ent = nl_.entries();
  auto gather = [&](std::int64_t q) {
    Vec3 f, t;
    for (std::int64_t e = off[q]; e < off[q + 1]; ++e) {
      std::int64_t k = ent[e];
      if (k >= 0) {
        f += pair_forces_[k].f_on_i;
        t += pair_forces_[k].t_on_i;
      } else {
        f -= pair_forces_[~k].f_on_i;
        t += pair_forces_[~k].t_on_j;
      }
    }
    p_.f[q] = f;
    p_.t[q] = t;
  };
  parallel_for(static_cast<std::int64_t>(p_.size()), gather);
}

void DemSystem::step() {
  if (!forces_ready_) compute_forces();
  const int max = max_threads();
  if (max > 1 && runs_parallel(static_cast<std::int64_t>(nl_.pairs().size()))) {
    const TeamSize team(threads_.begin(max));
    advance();
    threads_.end();
  } else {
    advance();
  }
  if (step_ % 256 == 0) check_state();
}

void DemSystem::advance() {
  if (parallel_step_applies()) {
    parallel_step();
  } else {
    const std::int64_t n = static_cast<std::int64_t>(p_.size());
    // The neighbour list's rebuild test (NeighborList::needs_rebuild) in the drift loop, in parallel: the
    // same test of the same positions, not a serial pass of its own (the reference twin: the serial pass,
    // and the kick and drift one particle at a time).
    const bool tracked = !reference_ && nl_.built_for(p_.size());
    const VerletArrays a = verlet_arrays(tracked);
    bool far = false;
    if (reference_) {
      parallel_for(n, [&](std::int64_t q) {
        kick_one(a, static_cast<std::size_t>(q));
        p_.x[q] += dt_ * p_.v[q];
      });
    } else {
      far = parallel_any_ranges(n, kVerletChunk, [&](std::int64_t b, std::int64_t e) { return kick_drift(a, b, e); });
    }
    time_ += dt_;
    ++step_;
    compute_forces(tracked ? (far ? 1 : 0) : -1);
    closing_kick();
  }
}

void DemSystem::check_state() const {
  for (std::size_t q = 0; q < p_.size(); ++q) {
    if (!isfinite(p_.x[q]) || !isfinite(p_.v[q]) || !isfinite(p_.w[q]))
      throw DemInstability(fmt::format("DEM: non-finite state of particle {} at step {} (t = {:.6g} s); "
                                       "reduce the time step",
                                       q, step_, time_));
    // A particle faster than one radius per step has certainly blown up.
    if (norm(p_.v[q]) * dt_ > p_.r[q])
      throw DemInstability(fmt::format("DEM: particle {} moves more than its radius per step at step {} "
                                       "(|v| = {:.3g} m/s): energy explosion; reduce the time step",
                                       q, step_, norm(p_.v[q])));
  }
}

double DemSystem::translational_kinetic_energy() const {
  double e = 0.0;
  for (std::size_t q = 0; q < p_.size(); ++q) e += 0.5 * p_.m[q] * norm2(p_.v[q]);
  return e;
}

double DemSystem::kinetic_energy() const {
  double e = translational_kinetic_energy();
  for (std::size_t q = 0; q < p_.size(); ++q) e += 0.5 * p_.I[q] * norm2(p_.w[q]);
  return e;
}

int DemSystem::active_contacts() const {
  int c = 0;
  for (const auto& pr : nl_.pairs()) c += pr.state.active ? 1 : 0;
  return c;
}

int DemSystem::wall_contacts() const {
  int c = 0;
  for (const auto& wc : walls_)
    for (const auto& s : wc.state) c += s.active ? 1 : 0;
  return c;
}

std::vector<int> DemSystem::contacts_per_particle() const {
  std::vector<int> c(p_.size(), 0);
  for (const auto& pr : nl_.pairs())
    if (pr.state.active) {
      ++c[pr.i];
      ++c[pr.j];
    }
  return c;
}

Vec3 DemSystem::momentum() const {
  Vec3 P;
  for (std::size_t q = 0; q < p_.size(); ++q) P += p_.m[q] * p_.v[q];
  return P;
}

Vec3 DemSystem::angular_momentum() const {
  Vec3 L;
  for (std::size_t q = 0; q < p_.size(); ++q) L += p_.m[q] * cross(p_.x[q], p_.v[q]) + p_.I[q] * p_.w[q];
  return L;
}

}  // namespace agglo::dem
