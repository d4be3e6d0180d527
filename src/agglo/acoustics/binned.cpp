#include "agglo/acoustics/binned.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

#include "agglo/acoustics/cell_events.hpp"
#include "agglo/core/rng.hpp"

namespace agglo::acoustics {

namespace {

constexpr std::size_t kMaxMechanisms = 16;
// Classes: size class s = floor(log10(d / 1e-12 m) kSizeClassesPerDecade), clamped to [0, kSizeClasses);
// weight class q = floor(log4 w), clamped to [0, kWeightClasses). Clamping merges extreme classes,
// which only loosens their bounds.
constexpr int kSizeClasses = 14 * 8;
constexpr int kWeightClasses = 128;

// True if two bounds are equal in every field a kernel reads (then cached majorants stay valid).
bool same_bounds(const CellBounds& x, const CellBounds& y) {
  return x.d_max == y.d_max && x.vol_max == y.vol_max && x.dl_max == y.dl_max && x.ccd_max == y.ccd_max &&
         x.w_max == y.w_max && x.speed_dev_max == y.speed_dev_max && x.cbar_max == y.cbar_max &&
         x.diff_max == y.diff_max && x.gap_max == y.gap_max && x.vref[0] == y.vref[0] && x.vref[1] == y.vref[1] &&
         x.vref[2] == y.vref[2];
}

class BinnedCell {
 public:
  BinnedCell(SampleSet& p, const std::uint32_t* idx, std::size_t n, std::uint64_t cell, std::uint64_t step,
             const CollisionContext& ctx, CollisionStats& st, std::uint32_t* local_of, BinnedGroups& g);
  void run(bool reuse);

 private:
  std::uint32_t class_of(std::size_t i) const;
  std::uint32_t group_for(std::uint32_t key);
  void insert(std::uint32_t a);
  void remove(std::uint32_t a);
  void build();
  void moved(std::size_t i);
  double pair_count(std::uint32_t a, std::uint32_t b) const;
  double first_step_candidates() const;
  void process_row(std::uint32_t a, double h);
  double row_rates(std::uint32_t a, bool all);
  double row_entry(std::uint32_t a, std::uint32_t b);
  const double* majorant_entry(std::uint32_t a, std::uint32_t b);
  std::uint32_t pick(std::uint32_t g, std::uint32_t exclude);
  bool candidate(std::uint32_t a, std::uint32_t b, const double* M);

  SampleSet& p;
  const std::uint32_t* idx;
  const std::size_t n;
  const CollisionContext& ctx;
  CollisionStats& st;
  std::uint32_t* local_of;
  const Kernel& K;
  const double Vc, per_ln;
  CounterRng rng;
  CellEvents events;
  const bool need_r, excl;
  const std::size_t nm;
  BinnedGroups& G;
  std::vector<BinnedGroup>& groups;
  std::vector<std::uint32_t>&group_of, &pos_of;
  std::vector<std::uint8_t>& grouped;
  std::vector<double> row_;  // candidate rates over n_a of the row a being processed
  std::vector<double> cum_;  // their running sums (partner group drawn by bisection)
  std::uint64_t row_version_ = 0;     // version of group a when row_ was computed
  std::vector<std::uint32_t> changed_;  // groups whose count or bounds changed since row_ was updated
};

BinnedCell::BinnedCell(SampleSet& p_, const std::uint32_t* idx_, std::size_t n_, std::uint64_t cell,
                       std::uint64_t step, const CollisionContext& ctx_, CollisionStats& st_, std::uint32_t* local_of_,
                       BinnedGroups& g)
    : p(p_), idx(idx_), n(n_), ctx(ctx_), st(st_), local_of(local_of_), K(*ctx_.kernel),
      Vc(ctx_.domain.cell_volume()), per_ln(kSizeClassesPerDecade / std::log(10.0)),
      rng(ctx_.seed, 0x200000000ULL + cell, step), events(p_, idx_, n_, ctx_, st_, rng), need_r(K.needs_distance()),
      excl(K.settings().exclude_same_population), nm(K.mechanism_count()), G(g), groups(g.groups), group_of(g.group_of),
      pos_of(g.pos_of), grouped(g.grouped) {}

std::uint32_t BinnedCell::class_of(std::size_t i) const {
  const double s = std::floor((std::log(p.d[i]) - std::log(1e-12)) * per_ln);
  const int sc = static_cast<int>(std::clamp(s, 0.0, static_cast<double>(kSizeClasses - 1)));
  const int wc = std::clamp(std::ilogb(p.w[i]) / 2, 0, kWeightClasses - 1);
  return static_cast<std::uint32_t>(sc * kWeightClasses + wc);
}

// Group of class `key` (open addressing over G.slots; a new group is opened when the class has none).
std::uint32_t BinnedCell::group_for(std::uint32_t key) {
  if (G.slots.size() < 4 * (G.count + 1)) {  // keep the table at most a quarter full
    std::vector<std::uint64_t> old(std::bit_ceil(std::max<std::size_t>(64, 8 * (G.count + 1))), 0);
    old.swap(G.slots);
    for (std::size_t g = 0; g < G.count; ++g) {
      std::size_t h = (groups[g].key * 0x9E3779B1u) & (G.slots.size() - 1);
      while (G.slots[h] != 0) h = (h + 1) & (G.slots.size() - 1);
      G.slots[h] = (static_cast<std::uint64_t>(groups[g].key) + 1) << 32 | g;
    }
  }
  const std::size_t mask = G.slots.size() - 1;
  std::size_t h = (key * 0x9E3779B1u) & mask;
  for (; G.slots[h] != 0; h = (h + 1) & mask)
    if ((G.slots[h] >> 32) == static_cast<std::uint64_t>(key) + 1) return static_cast<std::uint32_t>(G.slots[h]);
  const auto g = static_cast<std::uint32_t>(G.count++);
  if (groups.size() < G.count) groups.emplace_back();
  groups[g].members.clear();
  groups[g].cb = CellBounds{};
  groups[g].version = ++G.clock;
  groups[g].cb.need_cbar = K.needs_thermal_speed();
  groups[g].key = key;
  G.slots[h] = (static_cast<std::uint64_t>(key) + 1) << 32 | g;
  return g;
}

void BinnedCell::insert(std::uint32_t a) {
  const std::size_t i = idx[a];
  const std::uint32_t g = group_for(class_of(i));
  group_of[a] = g;
  pos_of[a] = static_cast<std::uint32_t>(groups[g].members.size());
  groups[g].members.push_back(a);
  grouped[a] = 1;
}

void BinnedCell::remove(std::uint32_t a) {
  auto& m = groups[group_of[a]].members;
  const std::uint32_t last = m.back();
  m[pos_of[a]] = last;
  pos_of[last] = pos_of[a];
  m.pop_back();
  grouped[a] = 0;
}

// Groups of the live samples; each group's reference velocity is its mean velocity.
void BinnedCell::build() {
  G.count = 0;
  std::fill(G.slots.begin(), G.slots.end(), 0);
  group_of.assign(n, 0);
  pos_of.assign(n, 0);
  grouped.assign(n, 0);
  for (std::uint32_t a = 0; a < n; ++a) {
    local_of[idx[a]] = a;
    if (p.w[idx[a]] > 0.0) insert(a);
  }
  for (std::size_t k = 0; k < G.count; ++k) {
    BinnedGroup& g = groups[k];
    g.version = ++G.clock;
    double v[3] = {0.0, 0.0, 0.0};
    for (const std::uint32_t a : g.members) {
      v[0] += p.vx[idx[a]];
      v[1] += p.vy[idx[a]];
      v[2] += p.vz[idx[a]];
    }
    for (int c = 0; c < 3; ++c) g.cb.vref[c] = v[c] / static_cast<double>(g.members.size());
    for (const std::uint32_t a : g.members) g.cb.include(p, idx[a], *ctx.gas);
    K.prepare(g.cb);
  }
}

// Sample i changed (size, weight, velocity): regroup it and let its group's bounds take it in.
void BinnedCell::moved(std::size_t i) {
  const std::uint32_t a = local_of[i];
  if (grouped[a]) {
    changed_.push_back(group_of[a]);
    remove(a);
  }
  if (!(p.w[i] > 0.0)) return;
  insert(a);
  changed_.push_back(group_of[a]);
  CellBounds& cb = groups[group_of[a]].cb;
  const CellBounds before = cb;
  cb.include(p, i, *ctx.gas);
  K.prepare(cb);
  if (!same_bounds(before, cb)) groups[group_of[a]].version = ++G.clock;
}

double BinnedCell::pair_count(std::uint32_t a, std::uint32_t b) const {
  const double na = static_cast<double>(groups[a].members.size()), nb = static_cast<double>(groups[b].members.size());
  return a == b ? 0.5 * na * (na - 1.0) : na * nb;
}

// Uniform member of group g other than local position `exclude`.
std::uint32_t BinnedCell::pick(std::uint32_t g, std::uint32_t exclude) {
  const auto& m = groups[g].members;
  const bool skip = exclude != UINT32_MAX;
  const std::size_t range = m.size() - (skip ? 1 : 0);
  std::size_t k = std::min(range - 1, static_cast<std::size_t>(rng.uniform() * static_cast<double>(range)));
  if (skip && k >= pos_of[exclude]) ++k;
  return m[k];
}

// One candidate of groups (a, b): returns true if it collided (the groups changed).
bool BinnedCell::candidate(std::uint32_t a, std::uint32_t b, const double* M) {
  ++st.trials;
  double u = rng.uniform() * M[nm];
  std::size_t k = 0;
  while (k + 1 < nm && u >= M[k]) u -= M[k++];
  if (!(M[k] > 0.0)) return false;
  const std::uint32_t la = pick(a, UINT32_MAX);
  const std::uint32_t lb = pick(b, a == b ? la : UINT32_MAX);
  const std::size_t i = idx[la], j = idx[lb];
  if (excl && p.pop[i] == p.pop[j]) return false;
  ++st.kernel_evals;
  const double r = need_r ? pair_distance(p, i, j, ctx.domain) : 0.0;
  const double q = K.mechanism_beta(k, p, i, j, r) * std::max(p.w[i], p.w[j]);
  const double ratio = q / M[k];
  st.max_pn = std::max(st.max_pn, ratio);
  if (ratio > 1.0 + 1e-9) ++st.violations;
  if (!(rng.uniform() < ratio)) return false;
  events.collide(i, j);
  for (const std::uint32_t s : events.touched()) moved(s);
  events.clear_touched();
  return true;
}

// Majorants M_m(a, b), m < nm, then their sum at [nm] (cached while both groups are unchanged). The pointer
// is valid until the next call.
const double* BinnedCell::majorant_entry(std::uint32_t a, std::uint32_t b) {
  if (G.cache_cap < G.count) {
    G.cache_cap = std::bit_ceil(2 * G.count);
    G.cache_m.assign(G.cache_cap * G.cache_cap * (nm + 1), 0.0);
    G.cache_va.assign(G.cache_cap * G.cache_cap, 0);
    G.cache_vb.assign(G.cache_cap * G.cache_cap, 0);
  }
  const std::size_t e = a * G.cache_cap + b;
  double* m = G.cache_m.data() + e * (nm + 1);
  if (G.cache_va[e] != groups[a].version || G.cache_vb[e] != groups[b].version) {
    K.mechanism_bounds(groups[a].cb, groups[b].cb, m);
    const double wmax = std::max(groups[a].cb.w_max, groups[b].cb.w_max);
    m[nm] = 0.0;
    for (std::size_t k = 0; k < nm; ++k) m[nm] += (m[k] *= wmax);
    G.cache_va[e] = groups[a].version;
    G.cache_vb[e] = groups[b].version;
  }
  return m;
}

// Candidate rate of the pair (a, b) over n_a (the row's common factor) [1/s].
double BinnedCell::row_entry(std::uint32_t a, std::uint32_t b) {
  const double na = static_cast<double>(groups[a].members.size()), nb = static_cast<double>(groups[b].members.size());
  const double n = a == b ? 0.5 * (na - 1.0) : nb;
  return n > 0.0 && na > 0.0 ? n * majorant_entry(a, b)[nm] / Vc : 0.0;
}

// Candidate rates of the pairs (a, b), b >= a, over n_a into row_ (all of them, or after a collision only
// those of the groups it changed, unless group a's bounds changed); returns the row's total rate.
double BinnedCell::row_rates(std::uint32_t a, bool all) {
  if (all || groups[a].version != row_version_) {
    row_.assign(G.count - a, 0.0);
    for (std::uint32_t b = a; b < G.count; ++b) row_[b - a] = row_entry(a, b);
    row_version_ = groups[a].version;
    ++st.row_rate_updates;
  } else {
    row_.resize(G.count - a, 0.0);
    for (const std::uint32_t g : changed_)
      if (g >= a) row_[g - a] = row_entry(a, g);
  }
  changed_.clear();
  cum_.resize(row_.size());
  double sum = 0.0;
  for (std::size_t k = 0; k < row_.size(); ++k) cum_[k] = (sum += row_[k]);
  return static_cast<double>(groups[a].members.size()) * sum;
}

// Poisson process of the candidates of all pairs (a, b >= a) together over an interval h (total rate the
// sum of the pair rates, exponential gaps; b drawn with probability rate_ab / sum). The rates are
// recomputed after every collision.
void BinnedCell::process_row(std::uint32_t a, double h) {
  changed_.clear();
  double t = 0.0, R = row_rates(a, true);
  for (;;) {
    if (!(R > 0.0)) return;
    // u > R (h - t) already implies a gap beyond the interval (1 - exp(-x) <= x): no logarithm needed.
    const double u = rng.uniform();
    if (u > R * (h - t)) return;
    t -= std::log1p(-u) / R;
    if (t >= h) return;
    const double x = rng.uniform() * R / static_cast<double>(groups[a].members.size());
    auto k = static_cast<std::size_t>(std::upper_bound(cum_.begin(), cum_.end(), x) - cum_.begin());
    k = std::min(k, row_.size() - 1);
    while (k > 0 && !(row_[k] > 0.0)) --k;  // rounding at the end of the row
    if (!(row_[k] > 0.0)) continue;
    const auto b = static_cast<std::uint32_t>(a + k);
    if (candidate(a, b, majorant_entry(a, b))) R = row_rates(a, false);
  }
}

// Expected candidates of the whole step (an upper bound of its collisions) when the cell has no history.
double BinnedCell::first_step_candidates() const {
  double M[kMaxMechanisms], c = 0.0;
  for (std::uint32_t a = 0; a < G.count; ++a)
    for (std::uint32_t b = a; b < G.count; ++b) {
      K.mechanism_bounds(groups[a].cb, groups[b].cb, M);
      double m = 0.0;
      for (std::size_t k = 0; k < nm; ++k) m += M[k];
      c += pair_count(a, b) * m * std::max(groups[a].cb.w_max, groups[b].cb.w_max) * ctx.dt / Vc;
    }
  return c;
}

// Sub-steps: as many as keep the collisions of the cell's previous step below kMaxCollisionFraction of its
// live samples per sub-step (the group pairs are processed one after the other in each sub-step).
void BinnedCell::run(bool reuse) {
  if (!reuse) build();
  std::uint64_t live = 0;
  for (std::size_t g = 0; g < G.count; ++g) live += groups[g].members.size();
  st.particle_steps += live;
  const double expected = G.has_history ? static_cast<double>(G.last_collisions) : first_step_candidates();
  const double want = expected / (kMaxCollisionFraction * static_cast<double>(live));
  const double most = static_cast<double>(G.has_history ? kMaxSubsteps : kMaxFirstSubsteps);
  const auto nsub = static_cast<std::uint64_t>(std::clamp(std::ceil(want), 1.0, most));
  const std::uint64_t before = st.collisions;
  const double h = 0.5 * ctx.dt / static_cast<double>(nsub);
  for (std::uint64_t s = 0; s < nsub; ++s) {
    for (std::uint32_t a = 0; a < G.count; ++a) process_row(a, h);  // forward sweep over the rows, half a sub-step
    for (std::uint32_t a = static_cast<std::uint32_t>(G.count); a-- > 0;) process_row(a, h);  // backward, other half
  }
  G.last_collisions = st.collisions - before;
  G.has_history = true;
  st.subcycled += nsub > 1 ? 1 : 0;
  st.max_subcycles = std::max(st.max_subcycles, nsub);
}

}  // namespace

void binned_collide_cell(SampleSet& p, const std::uint32_t* idx, std::size_t n, std::uint64_t cell,
                         std::uint64_t step, const CollisionContext& ctx, CollisionStats& st, std::uint32_t* local_of,
                         BinnedGroups& groups, bool reuse) {
  reuse = reuse && groups.group_of.size() == n;
  std::size_t live = 0;
  if (reuse)
    for (std::size_t g = 0; g < groups.count; ++g) live += groups.groups[g].members.size();
  else
    for (std::size_t a = 0; a < n; ++a) live += p.w[idx[a]] > 0.0 ? 1 : 0;
  if (live < 2) {
    groups.group_of.clear();  // not reusable
    return;
  }
  BinnedCell(p, idx, n, cell, step, ctx, st, local_of, groups).run(reuse);
}

}  // namespace agglo::acoustics
