#include "agglo/acoustics/binned.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

#include "agglo/acoustics/cell_events.hpp"
#include "agglo/acoustics/rate_tree.hpp"
#include "agglo/core/rng.hpp"

namespace agglo::acoustics {

namespace {

constexpr std::size_t kMaxMechanisms = 16;
// Classes from the bits of the doubles: size class = biased binary exponent of d with its first
// kSizeBits mantissa bits, counted from d = 2^-40 m (~1e-12 m); weight class = binary exponent of w
// (>= 1) over kWeightOctavesPerClass. Both are clamped (merging extreme classes only loosens their bounds).
constexpr int kSizeBits = std::countr_zero(static_cast<unsigned>(kSizeClassesPerOctave));
static_assert(kSizeClassesPerOctave == 1 << kSizeBits, "kSizeClassesPerOctave must be a power of 2");
constexpr std::int64_t kSizeOrigin = 1023 - 40;
constexpr int kSizeClasses = 48 << kSizeBits;
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
             const CollisionContext& ctx, CollisionStats& st, std::uint32_t* local_of, BinnedGroups& g,
             const std::uint32_t* cell_of);
  void run(GroupReuse mode);

 private:
  std::uint32_t class_of(std::size_t i) const;
  std::uint32_t group_for(std::uint32_t key);
  void insert(std::uint32_t a);
  void remove(std::uint32_t a);
  void build();
  void follow();
  void store_ids();
  void retighten();
  void set_bounds(std::size_t k);
  void moved(std::size_t i);
  double first_step_candidates();
  void process_row(std::uint32_t a, double h);
  double full_row(std::uint32_t a);
  double update_row(std::uint32_t a);
  double row_entry(std::uint32_t a, std::uint32_t b);
  void ensure_cache();
  void refresh_majorant(std::uint32_t a, std::uint32_t b, std::size_t e);
  void pick_pair(std::uint32_t a, std::uint32_t b, std::uint32_t& la, std::uint32_t& lb);
  bool candidate(std::uint32_t a, std::uint32_t b);

  SampleSet& p;
  const std::uint32_t* idx;
  const std::size_t n;
  const std::uint64_t cell_;
  const std::uint32_t* cell_of_;  // cell of every sample (moving runs), else nullptr
  const CollisionContext& ctx;
  CollisionStats& st;
  std::uint32_t* local_of;
  const Kernel& K;
  const double Vc;
  CounterRng rng;
  CellEvents events;
  const bool need_r, excl;
  const std::size_t nm;
  BinnedGroups& G;
  std::vector<BinnedGroup>& groups;
  std::vector<std::uint32_t>&group_of, &pos_of;
  std::vector<std::uint8_t>& grouped;
  const double inv_vc;
  std::vector<double> scratch_;         // rates of a row before they enter row_
  RateTree row_;                        // candidate rates over n_a of the row a being processed [1/s]
  bool tree_stale_ = false;              // row_ not yet built from scratch_ (full_row)
  std::uint64_t row_version_ = 0;       // version of group a when row_ was computed
  std::size_t row_count_ = 0;           // number of groups then
  std::vector<std::uint32_t> changed_;  // groups whose count or bounds changed since row_ was updated
};

BinnedCell::BinnedCell(SampleSet& p_, const std::uint32_t* idx_, std::size_t n_, std::uint64_t cell,
                       std::uint64_t step, const CollisionContext& ctx_, CollisionStats& st_, std::uint32_t* local_of_,
                       BinnedGroups& g, const std::uint32_t* cell_of)
    : p(p_), idx(idx_), n(n_), cell_(cell), cell_of_(cell_of), ctx(ctx_), st(st_), local_of(local_of_), K(*ctx_.kernel),
      Vc(ctx_.domain.cell_volume()),
      rng(ctx_.seed, 0x200000000ULL + cell, step), events(p_, idx_, n_, ctx_, st_, rng), need_r(K.needs_distance()),
      excl(K.settings().exclude_same_population), nm(K.mechanism_count()), G(g), groups(g.groups), group_of(g.group_of),
      pos_of(g.pos_of), grouped(g.grouped), inv_vc(1.0 / Vc) {}

std::uint32_t BinnedCell::class_of(std::size_t i) const {
  const auto bd = std::bit_cast<std::uint64_t>(p.d[i]), bw = std::bit_cast<std::uint64_t>(p.w[i]);
  const auto s = static_cast<std::int64_t>(bd >> (52 - kSizeBits)) - (kSizeOrigin << kSizeBits);
  const auto q = (static_cast<std::int64_t>(bw >> 52) - 1023) / kWeightOctavesPerClass;
  const auto sc = std::clamp<std::int64_t>(s, 0, kSizeClasses - 1);
  const auto wc = std::clamp<std::int64_t>(q, 0, kWeightClasses - 1);
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
  G.size.resize(std::max(G.size.size(), G.count), 0.0);
  G.version.resize(std::max(G.version.size(), G.count), 0);
  groups[g].members.clear();
  groups[g].cb = CellBounds{};
  groups[g].cb.need_cbar = K.needs_thermal_speed();
  groups[g].key = key;
  G.size[g] = 0.0;
  G.version[g] = ++G.clock;
  G.slots[h] = (static_cast<std::uint64_t>(key) + 1) << 32 | g;
  ensure_cache();
  return g;
}

void BinnedCell::insert(std::uint32_t a) {
  const std::size_t i = idx[a];
  const std::uint32_t g = group_for(class_of(i));
  group_of[a] = g;
  pos_of[a] = static_cast<std::uint32_t>(groups[g].members.size());
  groups[g].members.push_back(a);
  G.size[g] += 1.0;
  grouped[a] = 1;
}

void BinnedCell::remove(std::uint32_t a) {
  const std::uint32_t g = group_of[a];
  auto& m = groups[g].members;
  const std::uint32_t last = m.back();
  m[pos_of[a]] = last;
  pos_of[last] = pos_of[a];
  m.pop_back();
  G.size[g] -= 1.0;
  grouped[a] = 0;
}

// Groups of the live samples.
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
  for (std::size_t k = 0; k < G.count; ++k) set_bounds(k);
}

// The groups of the previous step carried over to this step's list: members still in this cell (by their
// stored sample indices) at their new local positions, the live samples that arrived in the group of their
// class (opened if the cell has none), bounds from the members. Classes change only in collisions, which
// regroup the samples they change, so every group holds the samples of its class, as after build().
void BinnedCell::follow() {
  group_of.assign(n, 0);
  pos_of.assign(n, 0);
  grouped.assign(n, 0);
  for (std::uint32_t a = 0; a < n; ++a) local_of[idx[a]] = a;
  for (std::uint32_t g = 0; g < G.count; ++g) {
    BinnedGroup& b = groups[g];
    b.members.clear();
    for (const std::uint32_t i : b.ids) {
      if (cell_of_[i] != cell_ || !(p.w[i] > 0.0)) continue;  // left the cell
      const std::uint32_t a = local_of[i];
      group_of[a] = g;
      pos_of[a] = static_cast<std::uint32_t>(b.members.size());
      b.members.push_back(a);
      grouped[a] = 1;
    }
    G.size[g] = static_cast<double>(b.members.size());
  }
  for (std::uint32_t a = 0; a < n; ++a)
    if (!grouped[a] && p.w[idx[a]] > 0.0) insert(a);
  retighten();
}

// The members' sample indices at the end of a step (the next step's follow()).
void BinnedCell::store_ids() {
  for (std::size_t g = 0; g < G.count; ++g) {
    BinnedGroup& b = groups[g];
    b.ids.resize(b.members.size());
    for (std::size_t k = 0; k < b.members.size(); ++k) b.ids[k] = idx[b.members[k]];
  }
  G.ids_valid = true;
}

// The bounds of the kept groups from their present members only (those of former members are dropped).
void BinnedCell::retighten() {
  for (std::size_t k = 0; k < G.count; ++k) set_bounds(k);
}

// A group's bounds from its members, with their mean velocity as reference velocity; new version.
void BinnedCell::set_bounds(std::size_t k) {
  BinnedGroup& g = groups[k];
  g.cb = CellBounds{};
  g.cb.need_cbar = K.needs_thermal_speed();
  G.version[k] = ++G.clock;
  if (g.members.empty()) return;
  double v[3] = {0.0, 0.0, 0.0};
  for (const std::uint32_t a : g.members) {
    v[0] += p.vx[idx[a]];
    v[1] += p.vy[idx[a]];
    v[2] += p.vz[idx[a]];
  }
  for (int c = 0; c < 3; ++c) g.cb.vref[c] = v[c] / static_cast<double>(g.members.size());
  g.cb.include_all(p, idx, g.members.data(), g.members.size(), *ctx.gas);
  K.prepare(g.cb);
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
  const std::uint32_t g = group_of[a];
  changed_.push_back(g);
  CellBounds& cb = groups[g].cb;
  const CellBounds before = cb;
  cb.include(p, i, *ctx.gas);
  // Kernel::prepare derives diff_max and gap_max from d_min, mass_max and cbar_max only (cell_bounds.hpp):
  // with those unchanged it would write the same numbers again.
  if (cb.d_min != before.d_min || cb.mass_max != before.mass_max || cb.cbar_max != before.cbar_max) K.prepare(cb);
  if (!same_bounds(before, cb)) G.version[g] = ++G.clock;
}

// Members la of group a and lb of group b (lb != la), both uniform, from one uniform number: the digits
// left after choosing la choose lb (53 - log2(n_a) >= 21 bits for groups below 2^32 members).
void BinnedCell::pick_pair(std::uint32_t a, std::uint32_t b, std::uint32_t& la, std::uint32_t& lb) {
  const auto& ma = groups[a].members;
  const auto& mb = groups[b].members;
  const double x = rng.uniform() * static_cast<double>(ma.size());
  const std::size_t ka = std::min(ma.size() - 1, static_cast<std::size_t>(x));
  const double f = x - static_cast<double>(ka);
  const std::size_t range = mb.size() - (a == b ? 1 : 0);
  std::size_t kb = std::min(range - 1, static_cast<std::size_t>(f * static_cast<double>(range)));
  if (a == b && kb >= ka) ++kb;
  la = ma[ka];
  lb = mb[kb];
}

// One candidate of groups (a, b): returns true if it collided (the groups changed).
bool BinnedCell::candidate(std::uint32_t a, std::uint32_t b) {
  ++st.trials;
  const std::size_t e = a * G.cache_cap + b;
  const double* M = G.cache_m.data() + e * nm;
  std::size_t k = 0;
  if (nm > 1) {
    double u = rng.uniform() * G.cache_sum[e];
    while (k + 1 < nm && u >= M[k]) u -= M[k++];
  }
  const double Mk = M[k];
  if (!(Mk > 0.0)) return false;
  std::uint32_t la = 0, lb = 0;
  pick_pair(a, b, la, lb);
  const std::size_t i = idx[la], j = idx[lb];
  if (excl && p.pop[i] == p.pop[j]) return false;
  ++st.kernel_evals;
  const double r = need_r ? pair_distance(p, i, j, ctx.domain) : 0.0;
  const double ratio = K.mechanism_beta(k, p, i, j, r) * std::max(p.w[i], p.w[j]) / Mk;
  st.max_pn = std::max(st.max_pn, ratio);
  if (ratio > 1.0 + 1e-9) ++st.violations;
  if (!(rng.uniform() < ratio)) return false;
  events.collide(i, j);
  for (const std::uint32_t s : events.touched()) moved(s);
  events.clear_touched();
  return true;
}

// The pair-majorant cache holds every pair of the groups in use (re-laid out, all entries stale, when the
// number of groups outgrows it).
void BinnedCell::ensure_cache() {
  if (G.cache_cap >= G.count) return;
  G.cache_cap = std::bit_ceil(2 * G.count);
  const std::size_t pairs = G.cache_cap * G.cache_cap;
  G.cache_sum.assign(pairs, 0.0);
  G.cache_m.assign(pairs * nm, 0.0);
  G.cache_va.assign(pairs, 0);
  G.cache_vb.assign(pairs, 0);
}

// Majorants M_m(a, b) of entry e = a * cache_cap + b from the groups' bounds, and their sum.
void BinnedCell::refresh_majorant(std::uint32_t a, std::uint32_t b, std::size_t e) {
  double* m = G.cache_m.data() + e * nm;
  double M[kMaxMechanisms];
  K.mechanism_bounds(groups[a].cb, groups[b].cb, M);
  const double wmax = std::max(groups[a].cb.w_max, groups[b].cb.w_max);
  double sum = 0.0;
  for (std::size_t k = 0; k < nm; ++k) sum += (m[k] = M[k] * wmax);
  G.cache_sum[e] = sum;
  G.cache_va[e] = G.version[a];
  G.cache_vb[e] = G.version[b];
}

// Candidate rate of the pair (a, b), a <= b, over n_a (the row's common factor) [1/s].
// (No pair of group b, e.g. an empty group kept without motion: rate 0 without touching its majorant.)
double BinnedCell::row_entry(std::uint32_t a, std::uint32_t b) {
  const double nb = a == b ? 0.5 * (G.size[a] - 1.0) : G.size[b];
  if (!(nb > 0.0)) return 0.0;
  const std::size_t e = a * G.cache_cap + b;
  if (G.cache_va[e] != G.version[a] || G.cache_vb[e] != G.version[b]) refresh_majorant(a, b, e);
  return nb * G.cache_sum[e] * inv_vc;
}

// All candidate rates of the pairs (a, b >= a) into row_; returns the row's total rate.
// The tree of the rates is built only when the row draws a candidate (tree_stale_): most rows of a step
// draw none. The total is summed in the tree's order (RateTree::assign), so it is the tree's total.
double BinnedCell::full_row(std::uint32_t a) {
  scratch_.resize(G.count - a);
  double total = 0.0;
  for (std::uint32_t b = a; b < G.count; ++b) total += (scratch_[b - a] = row_entry(a, b));
  tree_stale_ = true;
  row_version_ = G.version[a];
  row_count_ = G.count;
  changed_.clear();
  ++st.row_rate_updates;
  return G.size[a] * total;
}

// After a collision: the rates of the groups it changed (all of them if group a's bounds grew or a group
// was opened); returns the row's total rate.
double BinnedCell::update_row(std::uint32_t a) {
  if (G.version[a] != row_version_ || G.count != row_count_) return full_row(a);
  for (std::size_t c = 0; c < changed_.size(); ++c) {
    const std::uint32_t g = changed_[c];
    if (g < a || std::find(changed_.begin(), changed_.begin() + static_cast<std::ptrdiff_t>(c), g) !=
                     changed_.begin() + static_cast<std::ptrdiff_t>(c))
      continue;
    row_.set(g - a, row_entry(a, g));
  }
  changed_.clear();
  return G.size[a] * row_.total();
}

// Poisson process of the candidates of all pairs (a, b >= a) together over an interval h (total rate the
// sum of the pair rates, exponential gaps; b drawn with probability rate_ab / sum). The rates are
// updated after every collision.
void BinnedCell::process_row(std::uint32_t a, double h) {
  if (!(G.size[a] > 0.0)) {  // an empty group (kept without motion): rate 0, nothing drawn
    ++st.row_rate_updates;
    return;
  }
  double t = 0.0, R = full_row(a);
  for (;;) {
    if (!(R > 0.0)) return;
    // u > R (h - t) already implies a gap beyond the interval (1 - exp(-x) <= x): no logarithm needed.
    const double u = rng.uniform();
    if (u > R * (h - t)) return;
    t -= std::log1p(-u) / R;
    if (t >= h) return;
    if (tree_stale_) {
      row_.assign(scratch_.data(), scratch_.size());
      tree_stale_ = false;
    }
    const std::size_t k = row_.find(rng.uniform() * row_.total());
    if (k == RateTree::npos) return;
    if (candidate(a, a + static_cast<std::uint32_t>(k))) R = update_row(a);
  }
}

// Expected candidates of the whole step (an upper bound of its collisions) when the cell has no history.
double BinnedCell::first_step_candidates() {
  double c = 0.0;
  for (std::uint32_t a = 0; a < G.count; ++a)
    for (std::uint32_t b = a; b < G.count; ++b) c += G.size[a] * row_entry(a, b) * ctx.dt;
  return c;
}

// Sub-steps: as many as keep the collisions of the cell's previous step below kMaxCollisionFraction of its
// live samples per sub-step (the group pairs are processed one after the other in each sub-step).
void BinnedCell::run(GroupReuse mode) {
  if (mode == GroupReuse::rebuild) build();
  if (mode == GroupReuse::follow) follow();
  if (mode == GroupReuse::retighten) retighten();
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
  if (cell_of_) store_ids();
  st.subcycled += nsub > 1 ? 1 : 0;
  st.max_subcycles = std::max(st.max_subcycles, nsub);
}

}  // namespace

void binned_collide_cell(SampleSet& p, const std::uint32_t* idx, std::size_t n, std::uint64_t cell,
                         std::uint64_t step, const CollisionContext& ctx, CollisionStats& st, std::uint32_t* local_of,
                         BinnedGroups& groups, GroupReuse mode, const std::uint32_t* cell_of) {
  if (mode == GroupReuse::follow ? !cell_of || !groups.ids_valid : groups.group_of.size() != n)
    mode = GroupReuse::rebuild;
  const bool reuse = mode == GroupReuse::keep || mode == GroupReuse::retighten;
  std::size_t live = 0;
  if (reuse)
    for (std::size_t g = 0; g < groups.count; ++g) live += groups.groups[g].members.size();
  else
    for (std::size_t a = 0; a < n; ++a) live += p.w[idx[a]] > 0.0 ? 1 : 0;
  if (live < 2) {
    groups.group_of.clear();  // not reusable
    groups.ids_valid = false;
    return;
  }
  BinnedCell(p, idx, n, cell, step, ctx, st, local_of, groups, cell_of).run(mode);
}

}  // namespace agglo::acoustics
