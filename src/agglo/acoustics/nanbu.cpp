#include "agglo/acoustics/nanbu.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "agglo/acoustics/cell_events.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/settings_acoustic.hpp"
#include "agglo/core/rng.hpp"

#if defined(__GNUC__) && !defined(__clang__)
#define AGGLO_UNROLL4 _Pragma("GCC unroll 4")
#else
#define AGGLO_UNROLL4
#endif

namespace agglo::acoustics {

CellBounds cell_bounds(const SampleSet& p, const std::uint32_t* idx, std::size_t n, const Kernel& k,
                       const Gas& gas, std::size_t* live) {
  CellBounds cb;
  cb.need_cbar = k.needs_thermal_speed();
  // Same maxima as calling cb.include for every live sample: the size maxima and the mean velocity in
  // one pass, the largest squared speed deviation from the mean in a second (sqrt once at the end: it is
  // monotone, so sqrt of the largest square is the value include() would have kept). The thermal speed
  // sqrt(8 k T / (pi m)) is non-increasing in m under correctly rounded division and sqrt, so its largest
  // value is that of the lightest live sample: one sqrt per cell instead of one per sample.
  // The running extremum is the second argument of std::max/min (the value kept when they are equal):
  // the same result for numbers (positive sizes, weights, masses; the state check of a moving run has
  // excluded NaN; without motion a NaN would now reach the bound instead of being passed over), and
  // x86's maxsd/minsd then update the running value in place (no register copy per sample and extremum).
  double sw = 0.0, mx = 0.0, my = 0.0, mz = 0.0;
  double d_max = 0.0, vol_max = 0.0, dl_max = 0.0, ccd_max = 0.0, w_max = 0.0, s2_max = 0.0;
  double m_min = std::numeric_limits<double>::infinity();
  const double *vx = p.vx.data(), *vy = p.vy.data(), *vz = p.vz.data(), *w = p.w.data(), *d = p.d.data();
  const double *dl = p.dl.data(), *ccd = p.ccd.data(), *mass = p.mass.data();
  // (Unrolled: the loop's own increment, compare and branch are a sixth of its instructions per sample;
  // the operations and their order stay those of the plain loop.)
  AGGLO_UNROLL4
  for (std::size_t a = 0; a < n; ++a) {
    const std::size_t i = idx[a];
    if (w[i] <= 0.0) continue;
    mx += vx[i];
    my += vy[i];
    mz += vz[i];
    sw += 1.0;
    d_max = std::max(d[i], d_max);
    dl_max = std::max(dl[i], dl_max);
    ccd_max = std::max(ccd[i], ccd_max);
    w_max = std::max(w[i], w_max);
    m_min = std::min(mass[i], m_min);
  }
  if (live) *live = static_cast<std::size_t>(sw);
  if (sw > 0.0) {
    cb.vref[0] = mx / sw;
    cb.vref[1] = my / sw;
    cb.vref[2] = mz / sw;
  }
  const double rx = cb.vref[0], ry = cb.vref[1], rz = cb.vref[2];
  AGGLO_UNROLL4
  for (std::size_t a = 0; a < n; ++a) {
    const std::size_t i = idx[a];
    if (w[i] <= 0.0) continue;
    const double ex = vx[i] - rx, ey = vy[i] - ry, ez = vz[i] - rz;
    s2_max = std::max(ex * ex + ey * ey + ez * ez, s2_max);
  }
  if (k.needs_volume())  // vol_max is used by the additive kernel only
    for (std::size_t a = 0; a < n; ++a)
      if (p.w[idx[a]] > 0.0) vol_max = std::max(vol_max, p.vol_s[idx[a]] + p.vol_l[idx[a]]);
  cb.d_max = d_max;
  cb.vol_max = vol_max;
  cb.dl_max = dl_max;
  cb.ccd_max = ccd_max;
  cb.w_max = w_max;
  cb.speed_dev2_max = s2_max;
  cb.speed_dev_max = s2_max > 0.0 ? std::sqrt(s2_max) : 0.0;
  if (cb.need_cbar && sw > 0.0) cb.cbar_max = std::max(cb.cbar_max, thermal_speed(gas, m_min));
  return cb;
}

double guard_pn(const SampleSet& p, std::size_t i, std::size_t N, const CellBounds& cb, const Kernel& k, double dt,
                double cell_volume) {
  return static_cast<double>(N) * k.bound(p, i, cb) * cb.w_max * dt / (2.0 * cell_volume);
}

namespace {

// The collision step of one cell: state shared by the steps of its samples.
class CellCollision {
 public:
  CellCollision(SampleSet& p, const std::uint32_t* idx, std::size_t n, std::uint64_t cell, std::uint64_t step,
                const CollisionContext& ctx, CollisionStats& st);
  void run();

 private:
  void collide(std::size_t i, std::size_t j);
  bool evaluate(std::size_t i, std::size_t j, double h, double thr);
  bool trial(std::size_t i, double h, double pbound);
  void plain_trial(std::size_t& a, double pe);
  bool skip_to_passing_trial(std::size_t& a, double pe);
  void subcycled_trials(std::size_t i);

  SampleSet& p;
  const std::uint32_t* idx;
  const std::size_t n;
  const std::uint64_t cell, step;
  const CollisionContext& ctx;
  CollisionStats& st;
  const Kernel& K;
  const std::size_t N;  // dead samples stay candidates (they are refilled when possible): the draw is uniform over n
  const double Vc, invN;
  std::size_t live_at_start = 0;  // live samples when the step began (set by cell_bounds)
  CellBounds cb;
  CounterRng rng;
  CellEvents events;
  const bool need_r, excl;
  double pcell = 0.0;  // cell-wide majorant probability of a full step
  // Every sample of the cell is live: true from the start if none is dead, false after the first
  // collision (which may kill or refill samples); then the live samples are counted.
  bool all_live = false;
  // log1p(-min(pe, 1 - 1e-16)) of the geometric skip for the pe it was computed for (pe changes only
  // when a collision changes the cell bounds): one logarithm per cell instead of one per passing trial.
  double skip_pe = -1.0, skip_log = 0.0;
};

CellCollision::CellCollision(SampleSet& p_, const std::uint32_t* idx_, std::size_t n_, std::uint64_t cell_,
                             std::uint64_t step_, const CollisionContext& ctx_, CollisionStats& st_)
    : p(p_), idx(idx_), n(n_), cell(cell_), step(step_), ctx(ctx_), st(st_), K(*ctx_.kernel),
      N(n_), Vc(ctx_.domain.cell_volume()), invN(1.0 / static_cast<double>(n_)),
      cb(cell_bounds(p_, idx_, n_, K, *ctx_.gas, &live_at_start)), rng(ctx_.seed, 0x100000000ULL + cell_, step_),
      events(p_, idx_, n_, ctx_, st_, rng), need_r(K.needs_distance()), excl(K.settings().exclude_same_population),
      all_live(live_at_start == n_) {}

// Outcome of a collision of samples i and j; the cell bounds take in every changed sample.
void CellCollision::collide(std::size_t i, std::size_t j) {
  events.collide(i, j);
  all_live = false;
  for (const std::uint32_t s : events.touched()) cb.include(p, s, *ctx.gas);
  events.clear_touched();
}

// Kernel evaluation of a draw that passed the majorant: collide iff P_ij > thr. Returns true if i
// collided (its state changed).
bool CellCollision::evaluate(std::size_t i, std::size_t j, double h, double thr) {
  if (excl && p.pop[i] == p.pop[j]) return false;
  ++st.kernel_evals;
  const double r = need_r ? pair_distance(p, i, j, ctx.domain) : 0.0;
  const double beta = K.beta(p, i, j, r);
  const double P = beta * std::max(p.w[i], p.w[j]) * h / (2.0 * Vc);
  st.max_pn = std::max(st.max_pn, P * static_cast<double>(N));
  if (P > invN * (1.0 + 1e-9)) ++st.violations;
  if (P > thr) {
    collide(i, j);
    return true;
  }
  return false;
}

// One Nanbu trial of sample i over an interval h with majorant probability pbound. Returns true if
// i collided (its state changed).
bool CellCollision::trial(std::size_t i, double h, double pbound) {
  ++st.trials;
  const double R = rng.uniform();
  std::size_t ja = static_cast<std::size_t>(R * static_cast<double>(N));
  if (ja >= N) ja = N - 1;
  const std::size_t j = idx[ja];
  if (j == i || p.w[j] <= 0.0) return false;
  const double thr = static_cast<double>(ja + 1) * invN - R;
  if (thr >= pbound) return false;  // majorant rejection: P_ij <= pbound <= thr
  return evaluate(i, j, h, thr);
}

// Majorant met for a full step but most trials pass it: one plain trial of sample idx[a++].
void CellCollision::plain_trial(std::size_t& a, double pe) {
  const std::size_t i = idx[a++];
  if (p.w[i] <= 0.0) return;
  ++st.particle_steps;
  st.max_bound_pn = std::max(st.max_bound_pn, pe);
  trial(i, ctx.dt, pcell);
  st.max_subcycles = std::max<std::uint64_t>(st.max_subcycles, 1);
}

// Fast path: the cell-wide majorant meets the bound for a full step. A trial (R, candidate
// ja = int(R N), threshold thr = (ja+1)/N - R) passes the majorant (thr < pcell) with probability
// N pcell, and then ja is uniform and thr uniform in (0, pcell). The samples whose trial passes are
// found by geometric skipping (one draw per passing trial instead of one per sample); the trials of
// the skipped samples are rejections and need no draw. Returns false when the cell is done.
bool CellCollision::skip_to_passing_trial(std::size_t& a, double pe) {
  std::size_t skip = n - a;
  if (pe > 0.0) {
    if (pe != skip_pe) {
      skip_pe = pe;
      skip_log = std::log1p(-std::min(pe, 1.0 - 1e-16));
    }
    const double g = std::floor(std::log1p(-rng.uniform()) / skip_log);
    if (g < static_cast<double>(n - a)) skip = static_cast<std::size_t>(g);
  }
  std::uint64_t live = all_live ? skip : count_positive(p.w.data(), idx, a, a + skip);
  a += skip;
  if (a < n && p.w[idx[a]] > 0.0) ++live;
  if (live > 0) {
    st.particle_steps += live;
    st.trials += live;
    st.max_bound_pn = std::max(st.max_bound_pn, pe);
    st.max_subcycles = std::max<std::uint64_t>(st.max_subcycles, 1);
  }
  if (a == n) return false;
  const std::size_t i = idx[a++];
  if (p.w[i] <= 0.0) return true;
  std::size_t ja = static_cast<std::size_t>(rng.uniform() * static_cast<double>(N));
  if (ja >= N) ja = N - 1;
  const std::size_t j = idx[ja];
  if (j == i || p.w[j] <= 0.0) return true;
  evaluate(i, j, ctx.dt, pcell * (1.0 - rng.uniform()));
  return true;
}

// Trials of sample i with its own majorant, the step sub-cycled so that N P_bound <= 1.
void CellCollision::subcycled_trials(std::size_t i) {
  ++st.particle_steps;
  double remaining = ctx.dt;
  std::uint64_t intervals = 0;
  bool first = true;
  while (remaining > 0.0 && p.w[i] > 0.0) {
    const double B = K.bound(p, i, cb);
    const double pn_full = static_cast<double>(N) * B * cb.w_max * remaining / (2.0 * Vc);
    if (first) st.max_bound_pn = std::max(st.max_bound_pn, pn_full);
    first = false;
    double nsub = std::max(1.0, std::ceil(pn_full * (1.0 + 1e-12)));
    if (nsub > 1.0 && ctx.strict)
      throw NumericalError(fmt::format("step {}: Nanbu bound P_ij <= 1/N violated in cell {} for particle {} "
                                       "(N P = {:.3g}) and {} = \"strict\"",
                                       step, cell, p.id[i], pn_full,
                                       settings::acoustic_settings().time.nanbu_guard.dotted()));
    if (intervals + nsub > static_cast<double>(ctx.max_subcycles))
      throw NumericalError(fmt::format("step {}: Nanbu bound cannot be met in cell {} for particle {}: needs "
                                       "{:.3g} sub-cycles > {} = {}",
                                       step, cell, p.id[i], nsub,
                                       settings::acoustic_settings().time.max_subcycles.dotted(), ctx.max_subcycles));
    const double h = remaining / nsub;
    const double pbound = B * cb.w_max * h / (2.0 * Vc);
    // Trials of length h until a collision changes i (then the bound is recomputed).
    bool changed = false;
    for (double s = 0; s < nsub && !changed; s += 1.0) {
      ++intervals;
      remaining -= h;
      changed = trial(i, h, pbound);
    }
    if (remaining < 1e-12 * ctx.dt) remaining = 0.0;
  }
  if (intervals > 1) ++st.subcycled;
  st.max_subcycles = std::max(st.max_subcycles, intervals);
}

void CellCollision::run() {
  const double pfac = ctx.dt / (2.0 * Vc);
  pcell = K.bound_cell(cb) * cb.w_max * pfac;
  std::uint64_t seen = st.collisions;
  std::size_t a = 0;
  while (a < n) {
    if (st.collisions != seen) {  // cell bounds changed
      pcell = K.bound_cell(cb) * cb.w_max * pfac;
      seen = st.collisions;
    }
    const double pe = pcell * static_cast<double>(N);
    if (pe > 0.25 && pe <= 1.0) {
      plain_trial(a, pe);
    } else if (pe <= 1.0) {
      if (!skip_to_passing_trial(a, pe)) break;
    } else {
      const std::size_t i = idx[a++];
      if (p.w[i] > 0.0) subcycled_trials(i);
    }
  }
}

}  // namespace

void collide_cell(SampleSet& p, const std::uint32_t* idx, std::size_t n, std::uint64_t cell, std::uint64_t step,
                  const CollisionContext& ctx, CollisionStats& st) {
  std::size_t live = 0;  // a cell needs two live samples: stop counting at the second
  for (std::size_t a = 0; a < n && live < 2; ++a) live += p.w[idx[a]] > 0.0 ? 1 : 0;
  if (live < 2) return;
  CellCollision(p, idx, n, cell, step, ctx, st).run();
}

}  // namespace agglo::acoustics

#undef AGGLO_UNROLL4
