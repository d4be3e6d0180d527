#include "agglo/acoustics/engine.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include <fmt/format.h>
#include <omp.h>

#include "agglo/core/error.hpp"

#if defined(__GNUC__) && !defined(__clang__)
#define AGGLO_SORT_UNROLL4 _Pragma("GCC unroll 4")
#else
#define AGGLO_SORT_UNROLL4
#endif

namespace agglo::acoustics {

namespace {
// Below this many samples a step is too short for a fork/join to pay off.
constexpr std::size_t kParallelMinSamples = 4096;
// Large sets are re-sorted by cell every kReorderEvery steps so that a cell's samples are contiguous.
constexpr std::size_t kReorderMinSamples = 100000;
constexpr std::uint64_t kReorderEvery = 64;
// Samples per piece of a thread's block in the motion pass (state check and cell index while in cache).
constexpr std::size_t kMotionChunk = 512;
// Runs of the Nanbu selection with at least kSortMinSamples (and fewer than kReorderMinSamples) samples
// store them sorted by cell, re-sorted every kResortEvery steps of a moving run, the canonical order kept.
constexpr std::size_t kSortMinSamples = kParallelMinSamples;
constexpr std::uint64_t kResortEvery = 64;

// The canonical ranks [0, n) shared out between the `team` threads of a step's counting sort: range
// of(r) = min(team - 1, floor(r mul / 2^32)) with mul = floor(team 2^32 / n), a multiply and a shift per
// sample instead of a division (r mul < team 2^32 fits 64 bits). Any split into contiguous ranges gives
// the same sort; this one is monotone in r and near n / team ranks each.
class RankRanges {
 public:
  RankRanges(std::size_t n, int team)
      : n_(n), last_(static_cast<std::uint64_t>(team - 1)), mul_(n > 0 ? (std::uint64_t(team) << 32) / n : 0) {}
  std::uint64_t of(std::uint64_t r) const { return std::min(last_, (r * mul_) >> 32); }
  // The first rank of range q (n for q = team): the smallest r with of(r) >= q (binary search).
  std::size_t first(std::uint64_t q) const {
    std::size_t lo = 0, hi = n_;
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (of(mid) >= q) hi = mid; else lo = mid + 1;
    }
    return lo;
  }

 private:
  std::size_t n_;
  std::uint64_t last_, mul_;
};
}  // namespace

// The per-sample loops of the motion pass (state check, cell index) also compiled for AVX2 with GCC on
// x86-64, picked by the loader where the processor has it: the same answers (a boolean, integer cells).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(AGGLO_NO_AVX2)
#define AGGLO_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define AGGLO_AVX2_CLONES
#endif

Engine::Engine(EngineSettings s)
    : s_(std::move(s)), kernel_(s_.kernel, s_.motion.gas, s_.motion.sound) {
  substeps_ = std::max(1, static_cast<int>(std::lround(s_.collision_dt / s_.motion_dt)));
  p_.structure_laws = structure_laws_of(s_.populations);
  p_.carries_charge = std::any_of(s_.populations.begin(), s_.populations.end(),
                                  [](const PopulationSpec& pop) { return pop.charged; });
  for (std::size_t k = 0; k < s_.populations.size(); ++k)
    sampled_.push_back(sample_population(s_.populations[k], static_cast<int>(k), s_.motion.domain, s_.seed,
                                         s_.motion.gas, s_.motion.sound, p_, s_.sampling));
  for (std::size_t i = 0; i < p_.size(); ++i) {
    switch (s_.initial_velocity) {
      case InitialVelocity::steady:
        if (s_.motion.integrator != Integrator::none) s_.motion.set_steady_velocity(p_, i, 0.0);
        break;
      case InitialVelocity::gas:
        p_.vx[i] = s_.motion.sound.gas_velocity(p_.x[i], 0.0);
        break;
      case InitialVelocity::rest: break;
    }
  }
  cell_stats_.resize(static_cast<std::size_t>(s_.motion.domain.num_cells()));
  bin();
}

std::uint64_t Engine::total_steps() const {
  return static_cast<std::uint64_t>(std::llround(s_.t_end / s_.collision_dt));
}

void Engine::refresh_all() {
  for (std::size_t i = 0; i < p_.size(); ++i) p_.refresh(i, s_.motion.gas, s_.motion.sound);
  bin();
}

AGGLO_AVX2_CLONES void Engine::compute_cells(std::size_t begin, std::size_t end) {
  const Domain& D = s_.motion.domain;
  const double fx = D.cells[0] / D.L[0], fy = D.cells[1] / D.L[1], fz = D.cells[2] / D.L[2];
  const int c0 = D.cells[0], c1 = D.cells[1], c2 = D.cells[2];
  const double* x = p_.x.data();
  const double* y = p_.y.data();
  const double* z = p_.z.data();
  std::uint32_t* co = cell_of_.data();
  for (std::size_t i = begin; i < end; ++i) {
    const int cx = std::min(c0 - 1, static_cast<int>(x[i] * fx));
    const int cy = std::min(c1 - 1, static_cast<int>(y[i] * fy));
    const int cz = std::min(c2 - 1, static_cast<int>(z[i] * fz));
    co[i] = static_cast<std::uint32_t>((cz * c1 + cy) * c0 + cx);
  }
}

AGGLO_AVX2_CLONES bool Engine::state_ok(std::size_t begin, std::size_t end) const {
  // Branch-free form of check_state's tests: v - v is 0 for finite v and NaN otherwise, so the sum
  // `nf` is 0 iff everything is finite; x < L iff x - L < 0. A false alarm (none is expected) only
  // costs a call of check_state. The answer does not depend on the order of the sums, minima and maxima
  // (a NaN or infinity makes nf NaN whatever the order), so the loop runs in SIMD lanes.
  const Domain& D = s_.motion.domain;
  const double Lx = D.L[0], Ly = D.L[1], Lz = D.L[2];
  double nf = 0.0, lo = 0.0, hi = -1.0;
  const double *px = p_.x.data(), *py = p_.y.data(), *pz = p_.z.data();
  const double *pvx = p_.vx.data(), *pvy = p_.vy.data(), *pvz = p_.vz.data(), *pw = p_.w.data(), *pm = p_.mass.data();
#if !defined(__clang__)  // (clang 14 cannot vectorize the min/max reductions and warns)
#pragma omp simd reduction(+ : nf) reduction(min : lo) reduction(max : hi)
#endif
  for (std::size_t i = begin; i < end; ++i) {
    const double x = px[i], y = py[i], z = pz[i], vx = pvx[i], vy = pvy[i], vz = pvz[i];
    const double w = pw[i], m = pm[i];
    nf += ((x - x) + (y - y)) + ((z - z) + (vx - vx)) + ((vy - vy) + (vz - vz)) + ((w - w) + (m - m));
    lo = std::min(lo, std::min(std::min(x, y), std::min(z, w)));
    hi = std::max(hi, std::max(std::max(x - Lx, y - Ly), z - Lz));
  }
  return nf == 0.0 && lo >= 0.0 && hi < 0.0;
}

void Engine::bin() {
  regroup_ = true;
  const std::size_t n = p_.size();
  cell_of_.resize(n);
  order_.resize(n);
  compute_cells(0, n);
  sort_cells();
}

// Counting sort by cell; a cell's samples in canonical order (stored order when that is canonical). The
// serial form (start, a false alarm of the state check, tests): a step's team sorts in move_pass and
// sort_range, with the same result.
void Engine::sort_cells() {
  const std::size_t n = p_.size();
  const std::size_t nc = static_cast<std::size_t>(s_.motion.domain.num_cells());
  start_.assign(nc + 1, 0);
  // (Unrolled: the loop overhead is a third of these loops' instructions; the same order of updates.)
  if (by_rank_.empty()) {
    AGGLO_SORT_UNROLL4
    for (std::size_t i = 0; i < n; ++i) ++start_[cell_of_[i] + 1];
  } else {  // (in canonical order also the counts: in stored order runs of one cell chain the increments)
    const std::uint32_t* by_rank = by_rank_.data();
    AGGLO_SORT_UNROLL4
    for (std::size_t r = 0; r < n; ++r) ++start_[cell_of_[by_rank[r]] + 1];
  }
  for (std::size_t c = 0; c < nc; ++c) start_[c + 1] += start_[c];
  fill_.assign(start_.begin(), start_.end() - 1);
  if (by_rank_.empty()) {
    AGGLO_SORT_UNROLL4
    for (std::size_t i = 0; i < n; ++i) order_[fill_[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  } else {
    const std::uint32_t* by_rank = by_rank_.data();
    AGGLO_SORT_UNROLL4
    for (std::size_t r = 0; r < n; ++r) order_[fill_[cell_of_[by_rank[r]]]++] = by_rank[r];
  }
}

// The counting sort of a step, range q of canonical ranks (RankRanges of a team of `team`; after move_pass
// counted every sample by range and cell): the samples of the range, placed with `fill` (nc slots of
// scratch). A cell's slots go to the ranges in order, so cell c's samples of range q start at start_[c]
// plus the cell's samples of the ranges before q, and within a range they are placed in rank order: the
// same order_ and start_ as sort_cells for any team (integer sums), whichever thread places a range.
// Range 0 writes start_.
void Engine::sort_range(std::size_t q, int team, std::uint32_t* fill) {
  const std::size_t n = p_.size();
  const std::size_t nc = static_cast<std::size_t>(s_.motion.domain.num_cells());
  const std::size_t tm = static_cast<std::size_t>(team);
  if (q >= tm) return;  // (a team smaller than the step's claims)
  std::uint32_t run = 0;  // samples in the cells before c
  for (std::size_t c = 0; c < nc; ++c) {
    std::uint32_t total = 0, before = 0;  // cell c's samples: all, and those of the ranges before q
    for (std::size_t u = 0; u < tm; ++u)
      for (std::size_t v = 0; v < tm; ++v) {
        const std::uint32_t k = thread_counts_[u][v * nc + c];
        total += k;
        before += v < q ? k : 0;
      }
    fill[c] = run + before;
    if (q == 0) start_[c] = run;
    run += total;
  }
  if (q == 0) start_[nc] = run;
  const RankRanges ranges(n, team);
  const std::size_t r0 = ranges.first(q), r1 = ranges.first(q + 1);
  const std::uint32_t* cell_of = cell_of_.data();
  std::uint32_t* order = order_.data();
  if (by_rank_.empty()) {
    AGGLO_SORT_UNROLL4
    for (std::size_t r = r0; r < r1; ++r) order[fill[cell_of[r]]++] = static_cast<std::uint32_t>(r);
  } else {
    const std::uint32_t* by_rank = by_rank_.data();
    AGGLO_SORT_UNROLL4
    for (std::size_t r = r0; r < r1; ++r) order[fill[cell_of[by_rank[r]]]++] = by_rank[r];
  }
}

bool Engine::sorts_storage() const {
  const std::size_t n = p_.size();
  return s_.sort_storage && n >= kSortMinSamples && n < kReorderMinSamples && s_.selection == Selection::nanbu;
}

// Stores the samples in the order of order_ (cells in turn; a cell's samples in canonical order), so that
// order_ becomes the identity and a block of cells holds a contiguous range of samples. Serial form: a
// step's team runs every part of reorder_pass, then finish_reorder on one thread.
void Engine::reorder_by_cell(bool keep_canonical) {
  reorder_pass(0, 1, keep_canonical, 1);
  finish_reorder(keep_canonical, 1);
}

// Part `part` of `parts` of a re-sort: its share of the sample arrays (SampleSet::permute), and for its
// range of new positions k the cell index and (keep_canonical) the canonical rank of the sample moved to k,
// the inverse and range_base_ for a team of `team`; into the *_next_ arrays (sized n by prepare_step), as
// the other parts still read rank_ and cell_of_.
void Engine::reorder_pass(int part, int parts, bool keep_canonical, int team) {
  const std::size_t n = p_.size(), t = static_cast<std::size_t>(part), tm = static_cast<std::size_t>(parts);
  p_.permute(order_, part, parts);
  const std::size_t k0 = t * n / tm, k1 = (t + 1) * n / tm;
  for (std::size_t k = k0; k < k1; ++k) cell_next_[k] = cell_of_[order_[k]];
  if (!keep_canonical) return;
  const RankRanges ranges(n, team);
  const std::uint64_t nc = static_cast<std::uint64_t>(s_.motion.domain.num_cells());
  for (std::size_t k = k0; k < k1; ++k) {
    const std::uint32_t r = rank_.empty() ? order_[k] : rank_[order_[k]];
    rank_next_[k] = r;
    by_rank_next_[r] = static_cast<std::uint32_t>(k);
    range_base_[k] = static_cast<std::uint32_t>(ranges.of(r) * nc);
  }
}

// The serial end of a re-sort (after every part of reorder_pass): keep_canonical: the canonical order stays
// (rank_), else the new storage order becomes the canonical order (large sets, as before).
void Engine::finish_reorder(bool keep_canonical, int team) {
  if (keep_canonical) {
    rank_.swap(rank_next_);
    by_rank_.swap(by_rank_next_);
    range_team_ = team;
  } else {
    forget_storage_order();
  }
  cell_of_.swap(cell_next_);
  for (std::size_t k = 0; k < order_.size(); ++k) order_[k] = static_cast<std::uint32_t>(k);
  regroup_ = true;
  sorted_at_ = step_;
  ++resorts_;
  fix_blocks();
}

void Engine::canonicalize() const {
  if (rank_.empty()) return;
  const std::size_t n = p_.size();
  p_.permute(by_rank_);
  std::vector<std::uint32_t> cells(n);
  for (std::size_t k = 0; k < n; ++k) cells[k] = cell_of_[by_rank_[k]];
  cell_of_ = std::move(cells);
  for (std::uint32_t& i : order_) i = rank_[i];
  forget_storage_order();
}

void Engine::forget_storage_order() const {
  rank_.clear();
  by_rank_.clear();
  range_team_ = 0;
  blocks_fixed_ = false;
}

// One block per thread of omp_get_max_threads(), each a contiguous range of cells holding about n / B
// samples; with sorted storage (order_ the identity) also a contiguous range of stored samples.
void Engine::fix_blocks() {
  split_blocks();
  for (std::size_t b = 0; b < block_cells_.size(); ++b) block_samples_[b] = start_[block_cells_[b]];
  blocks_fixed_ = true;
}

void Engine::split_blocks() {
  const std::size_t n = p_.size(), nc = start_.size() - 1;
  const std::size_t nb = static_cast<std::size_t>(std::max(1, omp_get_max_threads()));
  if (move_claims_.size() != nb) {
    move_claims_ = std::vector<BlockClaims>(nb);
    cell_claims_ = std::vector<BlockClaims>(nb);
  }
  block_cells_.assign(nb + 1, static_cast<std::uint32_t>(nc));
  block_samples_.assign(nb + 1, static_cast<std::uint32_t>(n));
  block_cells_[0] = block_samples_[0] = 0;
  for (std::size_t b = 1; b < nb; ++b) {
    const auto first = std::lower_bound(start_.begin(), start_.end(), static_cast<std::uint32_t>(b * n / nb));
    block_cells_[b] = std::max(block_cells_[b - 1], static_cast<std::uint32_t>(first - start_.begin()));
    block_cells_[b] = std::min(block_cells_[b], static_cast<std::uint32_t>(nc));
    block_samples_[b] = static_cast<std::uint32_t>(b * n / nb);
  }
  blocks_fixed_ = false;
}

double Engine::max_guard_pn(std::size_t* argmax) const {
  const Domain& D = s_.motion.domain;
  double m = 0.0;
  for (int c = 0; c < D.num_cells(); ++c) {
    const std::uint32_t* idx = order_.data() + start_[c];
    const std::size_t n = start_[c + 1] - start_[c];
    if (n < 2) continue;
    const CellBounds cb = cell_bounds(p_, idx, n, kernel_, s_.motion.gas);
    for (std::size_t a = 0; a < n; ++a) {
      const double pn = guard_pn(p_, idx[a], n, cb, kernel_, s_.collision_dt, D.cell_volume());
      if (pn > m && argmax) *argmax = rank_.empty() ? idx[a] : rank_[idx[a]];  // (canonical index)
      m = std::max(m, pn);
    }
  }
  return m;
}

void Engine::check_state() const {
  const Domain& D = s_.motion.domain;
  for (std::size_t r = 0; r < p_.size(); ++r) {
    const std::size_t i = by_rank_.empty() ? r : by_rank_[r];  // (in canonical order: the first bad sample)
    const bool finite = std::isfinite(p_.x[i]) && std::isfinite(p_.y[i]) && std::isfinite(p_.z[i]) &&
                        std::isfinite(p_.vx[i]) && std::isfinite(p_.vy[i]) && std::isfinite(p_.vz[i]) &&
                        std::isfinite(p_.w[i]) && std::isfinite(p_.mass[i]);
    if (!finite)
      throw NumericalError(fmt::format("step {} (t = {:.6g} s): particle {} has a non-finite state "
                                       "(x = {:g}, v = ({:g}, {:g}, {:g}), w = {:g})",
                                       step_, time(), p_.id[i], p_.x[i], p_.vx[i], p_.vy[i], p_.vz[i], p_.w[i]));
    if (p_.x[i] < 0.0 || p_.x[i] >= D.L[0] || p_.y[i] < 0.0 || p_.y[i] >= D.L[1] || p_.z[i] < 0.0 ||
        p_.z[i] >= D.L[2] || p_.w[i] < 0.0)
      throw NumericalError(fmt::format("step {} (t = {:.6g} s): particle {} lost (position ({:g}, {:g}, {:g}) m "
                                       "outside the box, or weight {:g} < 0)",
                                       step_, time(), p_.id[i], p_.x[i], p_.y[i], p_.z[i], p_.w[i]));
  }
}

// The shared state of a step's region, set before it: the blocks, the thread counts and fills of the sort
// (nt threads at most), the move claims and the result arrays of a re-sort; returns the re-sort due.
Engine::Resort Engine::prepare_step(bool move, int nt) {
  const std::size_t n = p_.size(), nc = static_cast<std::size_t>(s_.motion.domain.num_cells());
  if (!blocks_fixed_ || block_samples_.back() != n ||
      block_cells_.size() != static_cast<std::size_t>(std::max(1, omp_get_max_threads())) + 1)
    split_blocks();
  const std::size_t tn = static_cast<std::size_t>(nt);
  if (move && thread_counts_.size() < tn) {
    thread_counts_.resize(tn);
    thread_fill_.resize(tn);
  }
  for (std::size_t t = 0; move && t < tn; ++t) {
    thread_counts_[t].resize(tn * nc);
    thread_fill_[t].resize(nc);
  }
  if (move) start_.resize(nc + 1);
  for (std::size_t b = 0; b < move_claims_.size(); ++b)
    move_claims_[b].reset(static_cast<std::uint32_t>((block_samples_[b + 1] - block_samples_[b] + kMotionChunk - 1) /
                                                     kMotionChunk));
  if (sort_claims_.size() != tn) {
    sort_claims_ = std::vector<BlockClaims>(tn);
    resort_claims_ = std::vector<BlockClaims>(tn);
  }
  for (std::size_t t = 0; t < tn; ++t) {
    sort_claims_[t].reset(1);
    resort_claims_[t].reset(1);
  }
  const Resort resort = resort_due(step_ + 1);
  if (resort != Resort::none) {
    cell_next_.resize(n);
    if (resort == Resort::keep_canonical) {
      rank_next_.resize(n);
      by_rank_next_.resize(n);
      range_base_.resize(n);
    }
  }
  return resort;
}

// The re-sort of the storage at step `step` (the step counter after its increment): large sets every
// kReorderEvery steps (a new canonical order), sorted storage after blocks from another order and every
// kResortEvery steps of a moving run.
Engine::Resort Engine::resort_due(std::uint64_t step) const {
  const bool moving = s_.motion.integrator != Integrator::none;
  if (p_.size() >= kReorderMinSamples && step % kReorderEvery == 1 && (moving || step == 1))
    return Resort::new_canonical;
  if (sorts_storage() && (!blocks_fixed_ || (moving && step - sorted_at_ >= kResortEvery)))
    return Resort::keep_canonical;
  return Resort::none;
}

// One collision step in one OpenMP parallel region (one fork/join and two barriers per step; two more on
// the steps that re-sort the storage): motion, state check, cell index and the sort's counts of each
// sample; then the counting sort by cell, one range of canonical ranks per thread (sort_range), and every
// kResortEvery steps the re-sort of the storage, its arrays shared out (reorder_pass); the little left
// serial (bin_step) runs on one thread while the other ranges are placed; then the collision step of every
// cell. Each thread takes the same block in both passes: the stored samples of its cells at the last sort
// and those cells (a static partition, so a sample stays in one core's cache between the passes). Each
// part does the same per sample and per cell, in the same order, so results are bitwise the same for any
// thread count. Exceptions never leave the region: the serial
// part's is kept and rethrown, and the cells' messages are kept per cell (the lowest cell's is thrown).
void Engine::step() {
  const std::size_t n = p_.size();
  const bool moving = s_.motion.integrator != Integrator::none;
  // Without motion positions never change (collisions keep a sample in its cell): the cells stay valid.
  const bool move = moving || cell_of_.size() != n;
  if (move) {
    cell_of_.resize(n);
    order_.resize(n);
  }
  const CollisionContext ctx = collision_context();
  const int nc = static_cast<int>(s_.motion.domain.num_cells());
  std::vector<std::string> errors(static_cast<std::size_t>(nc));
  bool bad_state = false;
  std::exception_ptr serial_error;
  GroupReuse reuse = GroupReuse::rebuild;
  // The thread count changes only the wall time (threads_: one thread where T were slower here).
  const bool parallel = n >= kParallelMinSamples;
  const int nt = parallel ? threads_.begin(omp_get_max_threads()) : 1;
  const Resort resort = prepare_step(move, nt);
#pragma omp parallel num_threads(nt) if (parallel)
  {
    const int thread = omp_get_thread_num(), team = omp_get_num_threads();
    if (move) move_pass(thread, team, bad_state);
#pragma omp barrier
    bool bad = false;
#pragma omp atomic read
    bad = bad_state;
    const bool sorting = move && !bad, resorting = resort != Resort::none && !bad;
    auto serial = [&] {
      if (serial_error) return;
      try {
        reuse = bin_step(move, bad, resort, resorting, team);
      } catch (...) {
        serial_error = std::current_exception();
      }
    };
    // The sort's ranges and the re-sort's parts go to whichever thread claims them (block_claims.hpp: its
    // own first), so a thread the OS holds back does not hold up the step; the claimer of range 0 (which
    // wrote start_) runs the serial part unless a re-sort follows.
    if (sorting)
      share_blocks(sort_claims_, thread, team, [&](std::size_t q, std::size_t) {
        sort_range(q, team, thread_fill_[static_cast<std::size_t>(thread)].data());
        if (q == 0 && !resorting) serial();
      });
    if (resorting) {
#pragma omp barrier
      share_blocks(resort_claims_, thread, team, [&](std::size_t part, std::size_t) {
        try {
          reorder_pass(static_cast<int>(part), static_cast<int>(resort_claims_.size()),
                       resort == Resort::keep_canonical, team);
        } catch (...) {
#pragma omp critical(agglo_engine_error)
          if (!serial_error) serial_error = std::current_exception();
        }
      });
#pragma omp barrier
    }
    if (!sorting || resorting) {
#pragma omp single nowait
      serial();
    }
#pragma omp barrier
    if (!serial_error) collide_pass(ctx, reuse, errors, thread, team);
  }
  if (parallel) threads_.end();
  if (serial_error) std::rethrow_exception(serial_error);
  for (int c = 0; c < nc; ++c)
    if (!errors[static_cast<std::size_t>(c)].empty()) throw NumericalError(errors[static_cast<std::size_t>(c)]);
  for (int c = 0; c < nc; ++c) stats_.add(cell_stats_[c]);
}

// Motion over one collision step, state check and cell index of the thread's block of stored samples
// (then what is left of the others' blocks, block_claims.hpp): the first part of a step's parallel region.
// Sets bad_state if a piece failed the check.
void Engine::move_pass(int thread, int team, bool& bad_state) {
  const double t0 = time();
  const Motion& M = s_.motion;
  const bool moving = M.integrator != Integrator::none;
  bool ok = true;
  std::vector<std::uint32_t>& cnt = thread_counts_[static_cast<std::size_t>(thread)];
  const std::size_t nc = static_cast<std::size_t>(M.domain.num_cells());
  std::fill(cnt.begin(), cnt.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(team) * nc), 0u);
  std::uint32_t* counts = cnt.data();
  const RankRanges ranges(p_.size(), team);
  const std::uint32_t* rank = rank_.empty() ? nullptr : rank_.data();
  const std::uint32_t* base = rank && range_team_ == team ? range_base_.data() : nullptr;
  share_blocks(move_claims_, thread, team, [&](std::size_t block, std::size_t piece) {
    const std::size_t b = block_samples_[block] + piece * kMotionChunk;
    const std::size_t e = std::min<std::size_t>(block_samples_[block + 1], b + kMotionChunk);
    bool chunk_ok = true;
    if (moving) {
      M.advance(p_, b, e, t0, s_.collision_dt, substeps_);
      chunk_ok = state_ok(b, e);
    }
    if (chunk_ok) {  // only for valid positions (otherwise the step throws)
      compute_cells(b, e);
      const std::uint32_t* cell = cell_of_.data();
      if (team == 1)  // the sort's counts, by rank range (sort_range) and cell
        for (std::size_t i = b; i < e; ++i) ++counts[cell[i]];
      else if (base != nullptr)  // (q(rank) * cells precomputed at the re-sort)
        for (std::size_t i = b; i < e; ++i) ++counts[base[i] + cell[i]];
      else if (rank == nullptr)
        for (std::size_t i = b; i < e; ++i) ++counts[ranges.of(i) * nc + cell[i]];
      else
        for (std::size_t i = b; i < e; ++i) ++counts[ranges.of(rank[i]) * nc + cell[i]];
    }
    ok = ok && chunk_ok;
  });
  if (!ok) {
#pragma omp atomic write
    bad_state = true;
  }
}

// The serial part of a step (one thread: the one that sorted range 0, or after a re-sort): advances the step counter, throws on a bad state
// (after a false alarm of the fast test: the cells and the sort here), ends a re-sort (all of it here when
// the team did not run reorder_pass), else fixes the blocks; returns what the binned selection does with its
// groups this step.
GroupReuse Engine::bin_step(bool moved, bool bad_state, Resort resort, bool resorted, int team) {
  const std::size_t n = p_.size();
  const bool moving = s_.motion.integrator != Integrator::none;
  ++step_;
  if (bad_state) {
    check_state();        // throws with the message naming the first bad particle
    compute_cells(0, n);  // (not reached unless the fast test gave a false alarm)
    if (moved) sort_cells();
  }
  if (resort != Resort::none) {
    const bool keep = resort == Resort::keep_canonical;
    if (!resorted) reorder_pass(0, 1, keep, 1);
    finish_reorder(keep, resorted ? team : 1);
  } else if (!blocks_fixed_) {
    split_blocks();  // cells by this step's counts
  }
  const bool binned = s_.selection == Selection::binned;
  // Binned groups are kept while only collisions change the samples (no motion, same order) and follow the
  // samples that move between cells otherwise; rebuilt after a new order and every kRegroupEvery steps of
  // a moving run, their bounds recomputed every kRetightenEvery steps without motion (binned.hpp).
  const GroupReuse reuse = !binned || regroup_ ? GroupReuse::rebuild
                           : moving ? (step_ % kRegroupEvery == 0 ? GroupReuse::rebuild : GroupReuse::follow)
                           : step_ % kRetightenEvery == 0 ? GroupReuse::retighten
                                                          : GroupReuse::keep;
  regroup_ = false;
  for (std::size_t b = 0; b < cell_claims_.size(); ++b) cell_claims_[b].reset(block_cells_[b + 1] - block_cells_[b]);
  if (binned) {
    local_of_.resize(n);
    groups_.resize(static_cast<std::size_t>(s_.motion.domain.num_cells()));
  }
  return reuse;
}

CollisionContext Engine::collision_context() const {
  CollisionContext ctx;
  ctx.kernel = &kernel_;
  ctx.outcomes = &s_.outcomes;
  ctx.gas = &s_.motion.gas;
  ctx.sound = &s_.motion.sound;
  ctx.domain = s_.motion.domain;
  ctx.dt = s_.collision_dt;
  ctx.seed = s_.seed;
  ctx.strict = s_.strict_guard;
  ctx.max_subcycles = s_.max_subcycles;
  return ctx;
}

// One collision step in every cell of the thread's block: the second part of a step's parallel region. A
// cell's exception is kept as its message in errors (exceptions must not leave an OpenMP region).
void Engine::collide_pass(const CollisionContext& ctx, GroupReuse reuse, std::vector<std::string>& errors, int thread,
                          int team) {
  const std::uint64_t st = step_;
  const bool binned = s_.selection == Selection::binned;
  // Moving runs: the cell of every sample, for the binned groups that follow the samples.
  const std::uint32_t* cell_of = s_.motion.integrator != Integrator::none ? cell_of_.data() : nullptr;
  share_blocks(cell_claims_, thread, team, [&](std::size_t block, std::size_t k) {
    const std::size_t c = block_cells_[block] + k;
    cell_stats_[c] = CollisionStats{};
    const std::size_t b = start_[c], e = start_[c + 1];
    try {
      const auto cell = static_cast<std::uint64_t>(c);
      if (e - b < 2 && binned)
        groups_[static_cast<std::size_t>(c)].ids_valid = false;  // stale: the next step rebuilds them
      else if (binned)
        binned_collide_cell(p_, order_.data() + b, e - b, cell, st, ctx, cell_stats_[c], local_of_.data(),
                            groups_[static_cast<std::size_t>(c)], reuse, cell_of);
      else if (e - b >= 2)
        collide_cell(p_, order_.data() + b, e - b, cell, st, ctx, cell_stats_[c]);
    } catch (const std::exception& ex) {
      errors[c] = ex.what();
    }
  });
}

}  // namespace agglo::acoustics

#undef AGGLO_AVX2_CLONES
#undef AGGLO_SORT_UNROLL4
