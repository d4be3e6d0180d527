// The shared free flight of the runs of one case (approach_cache.hpp).
#include "agglo/impact/approach_cache.hpp"

#include <algorithm>
#include <limits>

#include "agglo/dem/dem_system.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"
#include "agglo/impact/impact_run.hpp"

namespace agglo::impact {

ApproachCache::ApproachCache(const ImpactCase& c, const dem::Particles& agglomerate, double budget)
    : c_(c), agglomerate_(agglomerate), budget_(budget) {}

ApproachCache::~ApproachCache() = default;

bool ApproachCache::applies(const ImpactCase& c) {
  const auto& d = c.dem;
  return !c.wall_impact && c.projectile.shape == "sphere" && d.walls.empty() && norm2(d.gravity) == 0.0 &&
         !d.gas.enabled && (!c.electrostatics || (c.coupling.grounded.empty() && c.coupling.es.hold != "pair_corrected"));
}

namespace {

// The heap memory of a kept state, roughly [bytes].
double kept_bytes(const ApproachCache::Kept& k) {
  const auto& p = k.dem.particles;
  const auto& c = k.coupling;
  const double n = static_cast<double>(p.size());
  return sizeof(k) + n * (6.0 * sizeof(Vec3) + 5.0 * sizeof(double) + sizeof(std::uint32_t)) +
         static_cast<double>(k.dem.neighbors.pairs.size() * sizeof(dem::Pair)) +
         static_cast<double>((c.force.size() + c.torque.size() + c.x_at_solve.size() + c.n_s.size() + c.prev_force.size() +
                              c.prev_torque.size()) * sizeof(Vec3)) +
         static_cast<double>((c.visible.size() + c.f_s.size() + c.u_s.size() + c.warm.ints.size() + c.warm.values.size()) * 8);
}

}  // namespace

std::shared_ptr<const ApproachCache::Kept> ApproachCache::at(std::size_t m) {
  const std::lock_guard<std::mutex> lock(mutex_);
  while (kept_.size() <= m) {
    if (!kept_.empty() && kept_.size() >= limit_) return nullptr;
    extend();
    if (kept_.size() == 1) limit_ = static_cast<std::size_t>(std::max(1.0, budget_ / kept_bytes(*kept_.front())));
  }
  return kept_[m];
}

// The agglomerate as ImpactRun integrates it (the same DEM parameters and time step, the same coupling,
// the forces of the launch state first), kStride steps at a time.
void ApproachCache::extend() {
  if (!sys_) {
    sys_ = std::make_unique<dem::DemSystem>(agglomerate_, run_params(c_));
    if (c_.electrostatics) {
      es_ = make_electrostatic_force(c_);
      sys_->set_external_force(es_.get());
    }
    sys_->compute_forces();
  }
  auto k = std::make_shared<Kept>();
  k->dem = sys_->state();
  if (const auto* ef = dynamic_cast<const ElectrostaticForce*>(es_.get())) {
    k->has_coupling = true;
    k->coupling = ef->state();
  }
  const auto& x = sys_->particles().x;
  for (long s = 0; s < kStride; ++s) {
    sys_->step();
    for (std::size_t q = 0; q < x.size(); ++q) k->reach = std::max(k->reach, norm(x[q] - k->dem.particles.x[q]));
  }
  kept_.push_back(std::move(k));
}

}  // namespace agglo::impact

namespace agglo::impact {

// Whether the projectile, at x at the step of `k`, stays clear of every particle of the agglomerate over the
// next kStride steps: its surface gap to each particle's kept position exceeds how far that particle moves
// (k.reach), so no pair of it engages. On true x has drifted to the step of the next kept state.
bool ImpactRun::projectile_clear(const ApproachCache::Kept& k, Vec3& x) const {
  const auto& p = sys_.particles();
  const Vec3 v = p.v[n_agg_];
  const double dt = sys_.dt();
  const double margin = k.reach + 1e-6 * p.r[n_agg_];  // and a rounding margin far above the norm's error
  Vec3 y = x;
  for (long s = 0; s <= ApproachCache::kStride; ++s) {
    for (std::size_t i = 0; i < n_agg_; ++i)
      if (!(norm(y - k.dem.particles.x[i]) - k.dem.particles.r[i] - p.r[n_agg_] > margin)) return false;
    if (s < ApproachCache::kStride) y += dt * v;  // the drift of DemSystem::advance, step by step
  }
  x = y;
  return true;
}

// Replaces the launch state by the latest kept state of the case's free flight that the run provably
// reaches without contact (approach_cache.hpp), with the projectile drifted to it; nothing when the run
// cannot share the free flight (a charged or dielectric projectile, a recorder, an aggregate projectile).
void ImpactRun::skip_free_flight(ApproachCache& cache) {
  const auto& p = sys_.particles();
  const std::size_t q = n_agg_;
  if (rec_ || p.size() != n_agg_ + 1 || !ApproachCache::applies(c_) ||
      (es_ && (p.q[q] != 0.0 || p.kappa[q] != c_.medium_permittivity)) || norm2(p.w[q]) != 0.0)
    return;
  auto k = cache.at(0);
  if (k->dem.particles.size() != n_agg_) return;
  Vec3 x = p.x[q];
  std::shared_ptr<const ApproachCache::Kept> start;
  Vec3 x_start;
  for (std::size_t m = 1; projectile_clear(*k, x); ++m) {
    k = cache.at(m);
    if (!k || !(k->dem.time - at_.t_launch < max_approach_)) break;  // the approach would have ended before
    start = k;
    x_start = x;
  }
  if (!start) return;
  ImpactState s = state();
  dem::Particles& sp = s.dem.particles;
  const dem::Particles& kp = start->dem.particles;
  std::copy(kp.x.begin(), kp.x.end(), sp.x.begin());
  std::copy(kp.v.begin(), kp.v.end(), sp.v.begin());
  std::copy(kp.w.begin(), kp.w.end(), sp.w.begin());
  std::copy(kp.f.begin(), kp.f.end(), sp.f.begin());
  std::copy(kp.t.begin(), kp.t.end(), sp.t.begin());
  sp.x[q] = x_start;
  s.dem.neighbors = start->dem.neighbors;  // the projectile's entry: far, so that the next step rebuilds the list
  s.dem.neighbors.x_at_build.push_back(Vec3{1.0, 1.0, 1.0} * std::numeric_limits<double>::infinity());
  s.dem.time = start->dem.time;
  s.dem.step = start->dem.step;
  s.dem.forces_ready = start->dem.forces_ready;
  if (s.has_coupling) {
    s.coupling = start->coupling;
    s.coupling.force.push_back(Vec3{});  // the projectile is outside the solve
    s.coupling.torque.push_back(Vec3{});
    if (!s.coupling.x_at_solve.empty()) s.coupling.x_at_solve.push_back(x_start);
    if (!s.coupling.prev_force.empty()) {
      s.coupling.prev_force.push_back(Vec3{});
      s.coupling.prev_torque.push_back(Vec3{});
    }
  }
  restore(s);
  shared_steps_ = start->dem.step;
}

}  // namespace agglo::impact
