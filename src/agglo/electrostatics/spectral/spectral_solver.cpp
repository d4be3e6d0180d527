// Spectral (spherical-harmonic) solver, docs/model.md §B.2 item 3. See spectral_solver.hpp.
#include "agglo/electrostatics/spectral/spectral_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>
#include <omp.h>

#include "agglo/core/cancel.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"
#include "agglo/electrostatics/keys.hpp"
#include "agglo/electrostatics/gmres.hpp"
#include "agglo/electrostatics/large_buffer.hpp"
#include "agglo/electrostatics/spectral/degree.hpp"
#include "agglo/electrostatics/spectral/far_field.hpp"
#include "agglo/electrostatics/spectral/harmonics.hpp"
#include "agglo/electrostatics/spectral/pivot_rotation.hpp"
#include "agglo/electrostatics/spectral/rotation.hpp"
#include "agglo/electrostatics/spectral/translation.hpp"
#include "agglo/electrostatics/sphere_mesh.hpp"
#include "agglo/electrostatics/validate_spheres.hpp"

namespace agglo::es {

namespace {

using constants::eps0;
using constants::pi;

// Most pairs per block of build_pairs and of the dense matvec_M (cancellation is polled between blocks;
// matvec_M holds a block's products: at most 2 kPairBlock (L+1)^2 numbers, block_end), and the work
// that closes a block early (sum of (L+1)^3 over its pairs; about 20 ms of products).
constexpr std::size_t kPairBlock = 128;
constexpr double kBlockWork = 1e7;
// Below this much work per block (sum of (L+1)^3 over its pairs; about 2 ms of products) a block runs
// serially. A parallel region costs microseconds on idle cores, but OpenMP's threads spin-wait after
// it, and on a machine with fewer free cores than threads the spinning thread holds a core the
// working one needs: a 5-sphere collide (ten pairs at L = 36, 0.3 ms per product) took 6.3 s on
// two threads with GOMP_SPINCOUNT=3000, 9.4 s on one and 36.6 s on two with the default spin count
// under a load of 4 (docs/electrostatics.md, "Threads").
constexpr double kParallelPairWork = 1e6;
// Element-wise passes over the unknowns (apply_system) run in parallel from this many numbers on.
constexpr std::size_t kSpectralParallelLength = std::size_t(1) << 18;
// choose_degree: pairs of spheres from this many spheres on are visited in parallel.
constexpr int kParallelDegreeSpheres = 200;
// The preconditioner's inner GMRES solves (coarse system, pair blocks, contact network): relative residual.
constexpr double kInnerTolerance = 1e-10;
// preconditioner = "coarse": the degrees of the coarse system (measured at N = 100, kappa_p = 15: 16, 15,
// 14, 11 GMRES iterations with 1, 2, 4, 8 against 17 unpreconditioned; docs/electrostatics.md, "Sixth session").
constexpr int kCoarseDegree = 8;
// preconditioner = "contact_low": the close pairs' products truncated to degrees <= kContactLowDegree and
// pair-frame orders <= kContactLowOrder (what carries the contact network's effect; docs/electrostatics.md).
constexpr int kContactLowDegree = 20;
constexpr int kContactLowOrder = 2;
// ... and its Neumann steps z_(k+1) = u - gamma M_low z_k from z_0 = u: P^-1 = I - X + X^2 (X = gamma M_low)
// with two. Measured (bench_spectral_far_field, rows fmm_pc_contact_low at N = 100, 200, 1000, one thread):
// 1, 2, 3, 4, 6 steps: kappa_p = 15 N = 1000 12, 10, 10, 10, 9 GMRES iterations, N = 100 11, 10, 9, 9, 9;
// kappa_p = 2.5 N = 1000 6, 5, 5, 5, 5; a step costs about 3 % of a product (callgrind). Two: never more
// iterations than one at any size, and the warm start's guess (I + X) beta_prev is then P beta_prev up to
// X^3 (with one step, up to X^2). docs/electrostatics.md, "Seventh session". Three (SolverOptions::
// contact_low_steps): one iteration fewer on the kappa_p = 15 acceptance rows at L = 43, 44, 47 (8 against 9),
// the same 4 on kappa_p = 2.5's, whose solve a third step makes dearer ("Eighth session"). The default,
// kContactLowSteps, is declared in solver.hpp.

// contact_low's GMRES (solve_kept): the operator's products M P^-1 v it keeps for the closing combination
// (the cycle's start and up to this many basis vectors; 15.5 MB each at N = 1000, L = 43, touched only as
// GMRES reaches them). Past it the solve takes GMRES's own explicit residual, one product more.
constexpr int kKeptProducts = 24;

// A block of matvec_M's pair products (SpectralSolver::index_blocks): pairs [begin, end) of the solver's
// pairs, whether it has the work to run in parallel (whether or not threads > 1), and its spheres
// [sphere_begin, sphere_end) in the solver's per-block sphere list.
struct PairBlock {
  std::size_t begin = 0, end = 0;
  bool parallel = false;
  std::size_t sphere_begin = 0, sphere_end = 0;
};
// One product to add to a sphere: `count` numbers at `offset` in the block's products.
struct BlockTerm {
  std::size_t offset = 0;
  int count = 0;
};

// Unknowns per sphere: scaled exterior coefficients beta_lm = B_lm / a^(l+1) [V], where the
// sphere's own potential outside is sum B_lm I_l^m(x - x_i). The external potential at sphere i
// is sum A_lm R_l^m(x - x_i) with scaled alpha_lm = a^l A_lm [V]. Reaction form (docs/model.md §B.2):
//   beta_lm = -gamma_l alpha_lm (l >= 1),  beta_00 = q / (4 pi eps0 kappa0 a).
class SpectralSolver final : public Solver {
 public:
  explicit SpectralSolver(const SolverOptions& opt) : opt_(opt) {
    far_options_.tolerance = far_field_tolerance(opt);
  }
  SpectralSolver(const SolverOptions& opt, const sh::FarFieldOptions& far) : opt_(opt), far_options_(far) {}
  std::string name() const override { return std::string(kSpectralSolver); }
  Solution solve(const Problem& p) override;
  // alpha = M beta for p at the degree solve() would choose (spectral_product()).
  std::vector<double> product(const Problem& p, const std::vector<double>& beta, const sh::FarFieldOptions* far,
                              int repeat);
  int degree(const Problem& p) {
    double est_err = 0.0;
    return choose_degree(p, est_err);
  }
  std::vector<SurfaceSample> surface() const override;
  std::vector<std::array<int, 3>> surface_triangles() const override;
  WarmStart warm_start() const override { return {{prev_L_, prev_N_}, {prev_beta_.begin(), prev_beta_.end()}}; }
  void set_warm_start(const WarmStart& w) override {
    prev_L_ = static_cast<int>(w.ints.at(0));
    prev_N_ = static_cast<int>(w.ints.at(1));
    prev_beta_.assign(w.values.begin(), w.values.end());
  }

 private:
  struct Pair {
    int i = 0, k = 0;   // x_k - x_i along the frame's z axis
    double ui = 0, uk = 0;  // a_i / t, a_k / t
    int L = 0;  // truncation degree of this pair
    int M = 0;  // truncation order in the pair frame
    bool pivot = false;  // rotate with P and the solver's pivot tables, else with R
    sh::FrameRotation R;
    sh::PivotRotation P;
    // far_field = "fmm" (the near pairs only): the translation's source scalings
    // (AxialTranslation::source_powers), kept instead of 2 (M + 1) std::pow calls per pair and product
    std::vector<double> powers;
  };
  // alpha = M beta (sphere-sphere part)
  void matvec_M(const double* beta, double* alpha);
  void index_blocks();
  void add_block(const PairBlock& blk, double* alpha) const;
  void pair_product(const Pair& pr, const double* beta, double* out_i, double* out_k, double* s) const;
  void pair_product_at(const Pair& pr, const double* b_i, const double* b_k, double* out_i, double* out_k,
                       double* s) const;
  // Right preconditioner (SolverOptions::preconditioner): z = P^-1 u, and u = P x (the warm start's
  // GMRES guess); the set-up after prepare().
  void prepare_preconditioner(const Problem& p);
  void precondition(const double* u, double* z);
  void precondition_forward(const double* x, double* u);
  GmresResult solve_warm_shifted(const LargeVector& rhs, const GmresOptions& go);
  GmresResult solve_kept(const LargeVector& b, LargeVector& u, const GmresOptions& go);
  bool close_kept(const LargeVector& b, const LargeVector& u, double tol, double& residual);
  void coarse_inverse(const double* u, double* z);
  void pair_block_inverse(const Pair& pr, const double* u, double* z);
  void contact_inverse(const double* u, double* z);
  void add_contact_products(const double* x, double* alpha) const;
  void build_contact_low(const Problem& p);
  void contact_low_products(const double* x);
  void index_contact_low();
  void apply_contact_low(const double* x, const double* u, double* z, double sign);
  void set_gamma(const Problem& p);
  void add_gamma_times(const double* x, const double* a, double* y) const;
  std::size_t block_end(std::size_t b0, double& work) const;
  std::size_t slot_size(const Pair& pr) const;
  int choose_degree(const Problem& p, double& est_err);
  void prepare(const Problem& p, int L);
  void build_pairs(const Problem& p);
  void applied_field(const Problem& p, LargeVector& alpha_ext, LargeVector& rhs);
  void apply_system(std::span<const double> x, std::span<double> y);
  GmresResult solve_multipoles(const Problem& p, const LargeVector& rhs, double tol);
  Solution forces_and_energy(const Problem& p) const;

  SolverOptions opt_;
  sh::AxialTranslation T_;
  std::vector<Pair> pairs_;
  std::unique_ptr<sh::SphereFarField> far_;  // far_field = "fmm": the well-separated pairs
  sh::PivotTables pivot_;                    // far_field = "fmm": quarter turns of the near pairs' rotations
  sh::FarFieldOptions far_options_;
  int L_ = 0, N_ = 0, nc_ = 0;
  std::vector<double> gamma_;  // per sphere, per l
  // per sphere ncoef(L) numbers (18 MB each at N = 1000, L = 47): on huge pages (large_buffer.hpp)
  LargeVector beta_, alpha_;
  std::vector<double> out_, scratch_;  // matvec_M: per-pair products of a block, per-thread scratch
  // matvec_M's blocks (index_blocks, fixed by prepare()): per block its pairs, largest first (blk_order_),
  // each pair's offset in out_ (blk_slot_), and the spheres it adds to, each with its terms in pair order
  std::vector<PairBlock> blocks_;
  std::vector<std::size_t> blk_order_, blk_slot_;
  std::vector<int> blk_sphere_;
  std::vector<std::size_t> blk_sphere_start_;  // blk_sphere_[t]'s terms: blk_term_[start[t], start[t + 1])
  std::vector<BlockTerm> blk_term_;
  // Blocks of one product with the work to run in parallel (whether or not threads > 1: an output
  // that does not depend on the thread count).
  long parallel_blocks_ = 0;
  // Whether alpha_ holds M beta_ (GMRES ended with its explicit residual at the solution).
  bool alpha_current_ = false;
  Problem last_;
  GmresWorkspace ws_;
  // preconditioner: the low-degree system (coarse), the matched pairs (indices of pairs_), P^-1 u of the
  // last operator application, coarse vectors
  bool pc_coarse_ = false, pc_pair_ = false, pc_contact_ = false, pc_contact_low_ = false;
  std::vector<Pair> low_pairs_;  // contact_low: the close pairs at kContactLowDegree, kContactLowOrder
  std::vector<double> low_out_;  // contact_low: each low pair's two products, 2 ncoef(kContactLowDegree) a pair
  // contact_low: per sphere, its products in low_out_ (offsets, in pair order), from low_start_[i] on
  std::vector<std::size_t> low_start_, low_slot_;
  // contact_low: whether its passes have the work to run in parallel (whether or not threads > 1)
  bool low_parallel_ = false;
  std::unique_ptr<SpectralSolver> coarse_;
  std::vector<std::size_t> matched_;
  LargeVector z_;
  // contact_low (solve_kept): M P^-1 of the vectors GMRES applied its operator to, n numbers each: the
  // cycle's start, then V(0), V(1), ... (kKeptProducts + 1 reserved, sized as they are reached)
  LargeVector kept_;
  std::vector<double> pc_uc_, pc_zc_;
  long inner_iterations_ = 0;  // inner GMRES iterations of the preconditioner in the last solve
  bool kept_closed_ = false;   // contact_low: the last solve's alpha_ came from the kept products (solve_kept)
  // warm start
  LargeVector prev_beta_;
  int prev_L_ = -1, prev_N_ = -1;
};

// L: the largest pair degree for the target over pairs with a polarisable sphere (capped), or max_degree;
// est_err: the largest error estimate at L (every pair when max_degree is set). Maxima do not depend on
// the order of the pairs, so the pairs are visited in parallel from kParallelDegreeSpheres spheres on.
int SpectralSolver::choose_degree(const Problem& p, double& est_err) {
  const int N = static_cast<int>(p.spheres.size());
  const bool threaded = N >= kParallelDegreeSpheres;
  const bool every_pair = opt_.max_degree > 0;
  auto skip = [&](const Sphere& a, const Sphere& b) {
    // a pair with no polarisable sphere needs only its monopoles
    return !every_pair && a.permittivity == p.medium_permittivity && b.permittivity == p.medium_permittivity;
  };
  int L = every_pair ? opt_.max_degree : 2;
  if (!every_pair) {
#pragma omp parallel for schedule(dynamic, 8) reduction(max : L) if (threaded)
    for (int i = 0; i < N; ++i)
      for (int k = i + 1; k < N; ++k) {
        const auto& a = p.spheres[i];
        const auto& b = p.spheres[k];
        if (skip(a, b)) continue;
        auto r = sh::limit_ratios(a.radius, b.radius, norm(b.center - a.center));
        L = std::max(L, sh::degree_for(r, opt_.target_accuracy));
      }
    L = std::min(L, opt_.max_degree_limit);
  }
  double e = 0.0;
#pragma omp parallel for schedule(dynamic, 8) reduction(max : e) if (threaded)
  for (int i = 0; i < N; ++i)
    for (int k = i + 1; k < N; ++k) {
      const auto& a = p.spheres[i];
      const auto& b = p.spheres[k];
      if (skip(a, b)) continue;
      auto r = sh::limit_ratios(a.radius, b.radius, norm(b.center - a.center));
      e = std::max(e, sh::error_estimate(r, L));
    }
  est_err = e;
  return L;
}

// One pair's contribution (rotate into the pair frame, axial translations both ways, rotate back),
// written (not added) to out_i, out_k (ncoef(pr.L) each); s = 4 ncoef(pr.L) of scratch.
void SpectralSolver::pair_product(const Pair& pr, const double* beta, double* out_i, double* out_k,
                                  double* s) const {
  pair_product_at(pr, beta + std::size_t(pr.i) * nc_, beta + std::size_t(pr.k) * nc_, out_i, out_k, s);
}

// pair_product with the two spheres' coefficients at b_i and b_k.
void SpectralSolver::pair_product_at(const Pair& pr, const double* b_i, const double* b_k, double* out_i,
                                     double* out_k, double* s) const {
  const int np = sh::ncoef(pr.L);
  double *bi = s, *bk = s + np, *ai = s + 2 * np, *ak = s + 3 * np;
  if (pr.pivot)
    pr.P.to_frame2(pivot_, pr.L, pr.M, b_k, b_i, bk, bi);
  else
    pr.R.to_frame2(pr.L, pr.M, b_k, b_i, bk, bi);
  // ai, ak: their frame orders <= pr.M written by the translation (add = false), the only ones the rotation
  // back reads (no zeroing first). out_i, out_k: written whole by the rotation back (add = false). Both the
  // same numbers as adding to zeros but for the sign of a zero, and alpha, which starts at +0, sums them to
  // the same bits either way.
  // source k seen from i sits at +t z; source i seen from k at -t z.
  T_.apply_pair(pr.L, pr.M, pr.ui, pr.uk, bk, bi, ai, ak, pr.powers.empty() ? nullptr : pr.powers.data(), false);
  if (pr.pivot)
    pr.P.from_frame2(pivot_, pr.L, pr.M, ai, ak, out_i, out_k, false);
  else
    pr.R.from_frame2(pr.L, pr.M, ai, ak, out_i, out_k, false);
}

// alpha = M beta. The pairs are taken in blocks (index_blocks): in each block's parallel region the pair
// products run first, largest first from a dynamic schedule (the last pair a thread takes is a small
// one), each into its own slot; then the block's spheres, each adding its terms in pair order
// (add_block), so alpha does not depend on the thread count. Cancellation is polled between blocks
// (never inside a parallel region, core/cancel.hpp): a block is at most kBlockWork of work.
void SpectralSolver::matvec_M(const double* beta, double* alpha) {
  const std::size_t nc = std::size_t(nc_), n = std::size_t(N_) * nc;
#pragma omp parallel for schedule(static) if (n >= kSpectralParallelLength)
  for (std::size_t c = 0; c < n; ++c) alpha[c] = 0.0;
  const int threads = omp_get_max_threads();
  scratch_.resize(std::max(scratch_.size(), std::size_t(threads) * 4 * nc));
  for (const PairBlock& blk : blocks_) {
    poll_cancel();
#pragma omp parallel if (threads > 1 && blk.parallel)
    {
      double* s = &scratch_[std::size_t(omp_get_thread_num()) * 4 * nc];
#pragma omp for schedule(dynamic, 1)
      for (std::size_t r = blk.begin; r < blk.end; ++r) {
        const std::size_t q = blk_order_[r];
        double* o = &out_[blk_slot_[q]];
        pair_product(pairs_[q], beta, o, o + slot_size(pairs_[q]), s);
      }
      add_block(blk, alpha);
    }
  }
  if (far_) far_->add(beta, alpha);
}

// alpha += the products of one block (out_), inside matvec_M's parallel region: the block's spheres are
// shared out dynamically (a sphere's terms differ by up to 20 times in length), each sphere adding its
// terms in pair order, so every number of alpha receives its terms in the same order at any thread count.
void SpectralSolver::add_block(const PairBlock& blk, double* alpha) const {
  const std::size_t nc = std::size_t(nc_);
#pragma omp for schedule(dynamic, 4)
  for (std::size_t t = blk.sphere_begin; t < blk.sphere_end; ++t) {
    double* al = alpha + std::size_t(blk_sphere_[t]) * nc;
    for (std::size_t e = blk_sphere_start_[t]; e < blk_sphere_start_[t + 1]; ++e) {
      const double* o = &out_[blk_term_[e].offset];
      for (int c = 0; c < blk_term_[e].count; ++c) al[c] += o[c];
    }
  }
}

// matvec_M's blocks (block_end): each block's pairs by decreasing degree (ties in pair order), each pair's
// offset in out_, and the spheres of the block with their terms in pair order; out_ sized for the
// largest block. Fixed for the pairs of prepare().
void SpectralSolver::index_blocks() {
  const std::size_t npairs = pairs_.size();
  blocks_.clear();
  blk_order_.resize(npairs);
  blk_slot_.resize(npairs);
  blk_sphere_.clear();
  blk_sphere_start_.assign(1, 0);
  blk_term_.clear();
  std::size_t most = 0;
  std::vector<std::pair<int, std::size_t>> touch;  // (sphere, 2 q + side) of one block
  for (std::size_t b0 = 0, b1; b0 < npairs; b0 = b1) {
    double work = 0.0;
    b1 = block_end(b0, work);
    PairBlock blk{b0, b1, b1 - b0 > 1 && work > kParallelPairWork, blk_sphere_.size(), 0};
    std::size_t used = 0;
    touch.clear();
    for (std::size_t q = b0; q < b1; ++q) {
      blk_slot_[q] = used;
      used += 2 * slot_size(pairs_[q]);
      touch.push_back({pairs_[q].i, 2 * q});
      touch.push_back({pairs_[q].k, 2 * q + 1});
    }
    most = std::max(most, used);
    std::iota(blk_order_.begin() + std::ptrdiff_t(b0), blk_order_.begin() + std::ptrdiff_t(b1), b0);
    std::stable_sort(blk_order_.begin() + std::ptrdiff_t(b0), blk_order_.begin() + std::ptrdiff_t(b1),
                     [&](std::size_t a, std::size_t b) { return pairs_[a].L > pairs_[b].L; });
    std::sort(touch.begin(), touch.end());  // by sphere, then in pair order
    for (std::size_t e = 0; e < touch.size(); ++e) {
      const auto [sphere, code] = touch[e];
      const Pair& pr = pairs_[code / 2];
      blk_term_.push_back({blk_slot_[code / 2] + (code % 2) * slot_size(pr), sh::ncoef(pr.L)});
      if (e + 1 == touch.size() || touch[e + 1].first != sphere) {
        blk_sphere_.push_back(sphere);
        blk_sphere_start_.push_back(blk_term_.size());
      }
    }
    blk.sphere_end = blk_sphere_.size();
    blocks_.push_back(blk);
  }
  out_.resize(most);
}

// End of the block of pair products that starts at pair b0: pairs are added until the block holds
// kBlockWork of work (sum of (L+1)^3) or its products fill 2 kPairBlock (L+1)^2 numbers (dense: kPairBlock
// pairs; fmm: a pair's products take ncoef(L_pair) each, so that the many low-degree near pairs share a
// block with enough touching pairs to run in parallel). `work` returns the block's work.
std::size_t SpectralSolver::block_end(std::size_t b0, double& work) const {
  std::size_t b1 = b0, used = 0;
  const std::size_t cap = kPairBlock * std::size_t(nc_);
  work = 0.0;
  while (b1 < pairs_.size() && work < kBlockWork && used + slot_size(pairs_[b1]) <= cap) {
    used += slot_size(pairs_[b1]);
    const double w = pairs_[b1++].L + 1.0;
    work += w * w * w;  // (L + 1)^3, exact: the same blocks as std::pow, without its cost per pair and product
  }
  return b1;
}

// Numbers of one of a pair's two products in a block (block_end).
std::size_t SpectralSolver::slot_size(const Pair& pr) const {
  return far_ ? std::size_t(sh::ncoef(pr.L)) : std::size_t(nc_);
}

// Pairs with their own truncation degree and frame order (at 1e-3 x target accuracy).
void SpectralSolver::build_pairs(const Problem& p) {
  const int N = N_;
  const std::size_t npairs = far_ ? far_->near_pairs().size() : std::size_t(N) * (N - 1) / 2;
  pairs_.resize(npairs);
  if (far_) {
    for (std::size_t q = 0; q < npairs; ++q) {
      pairs_[q].i = far_->near_pairs()[q][0];
      pairs_[q].k = far_->near_pairs()[q][1];
    }
  } else {
    std::size_t q = 0;
    for (int i = 0; i < N; ++i)
      for (int k = i + 1; k < N; ++k, ++q) {
        pairs_[q].i = i;
        pairs_[q].k = k;
      }
  }
  const double tol_pair = 1e-3 * opt_.target_accuracy;
  const bool pivots = far_ && !far_options_.stored_rotations;
  for (std::size_t b0 = 0; b0 < npairs; b0 += kPairBlock) {
    poll_cancel();
    const std::size_t b1 = std::min(npairs, b0 + kPairBlock);
    // the set-up of a pair costs about one product at the global degree (bound of its own degree)
    const bool parallel = omp_get_max_threads() > 1 && b1 - b0 > 1 &&
                          double(b1 - b0) * std::pow(L_ + 1.0, 3) > kParallelPairWork;
#pragma omp parallel for schedule(dynamic, 1) if (parallel)
    for (std::size_t r = b0; r < b1; ++r) {
      auto& pr = pairs_[r];
      const auto& a = p.spheres[pr.i];
      const auto& b = p.spheres[pr.k];
      Vec3 d = b.center - a.center;
      double t = norm(d);
      pr.ui = a.radius / t;
      pr.uk = b.radius / t;
      auto lr = sh::limit_ratios(a.radius, b.radius, t);
      pr.L = std::min(L_, std::max(2, sh::degree_for(lr, tol_pair)));
      pr.M = T_.order_cutoff(pr.L, pr.ui, pr.uk, tol_pair);
      pr.pivot = pivots && pr.L >= kPivotDegree;
      if (pr.pivot)
        pr.P.build(d, pr.L, pr.M);
      else
        pr.R.build(d, pr.L, pr.M);
      if (far_) sh::AxialTranslation::source_powers(std::min(pr.L, pr.M), pr.ui, pr.uk, pr.powers);
    }
  }
}

// gamma_l per sphere; the applied field's local coefficients alpha_ext (phi = -E.x, scaled by
// a^l) and the right-hand side rhs = -gamma alpha_ext (l >= 1), q / (4 pi eps0 kappa0 a) (l = 0).
void SpectralSolver::applied_field(const Problem& p, LargeVector& alpha_ext, LargeVector& rhs) {
  const int N = N_, L = L_;
  const double k0 = p.medium_permittivity;
  set_gamma(p);
  const std::size_t n = std::size_t(N) * nc_;
  alpha_ext.resize(n);  // every number is set below, sphere by sphere
  rhs.resize(n);  // (rhs: every number written, degree by degree)
  const double r2 = std::sqrt(2.0);
#pragma omp parallel for schedule(static) if (n >= kSpectralParallelLength)
  for (int i = 0; i < N; ++i) {
    const auto& s = p.spheres[i];
    double* ae = &alpha_ext[std::size_t(i) * nc_];
    std::fill(ae, ae + nc_, 0.0);
    const Vec3& E = p.external_field;
    ae[sh::idx(0, 0)] = -dot(E, s.center);
    if (L >= 1) {
      ae[sh::idx(1, 0)] = -s.radius * E.z;
      ae[sh::idx(1, 1)] = -r2 * s.radius * E.x;
      ae[sh::idx(1, -1)] = -r2 * s.radius * E.y;
    }
    double* b = &rhs[std::size_t(i) * nc_];
    for (int l = 1; l <= L; ++l)
      for (int m = -l; m <= l; ++m) b[sh::idx(l, m)] = -gamma_[i * (L + 1) + l] * ae[sh::idx(l, m)];
    b[0] = s.charge / (4 * pi * eps0 * k0 * s.radius);
  }
}

// gamma_l per sphere (l = 0: 0).
void SpectralSolver::set_gamma(const Problem& p) {
  const int N = N_, L = L_;
  const double k0 = p.medium_permittivity;
  gamma_.assign(std::size_t(N) * (L + 1), 0.0);
  for (int i = 0; i < N; ++i) {
    double ki = p.spheres[i].permittivity;
    for (int l = 1; l <= L; ++l) gamma_[i * (L + 1) + l] = (ki - k0) * l / ((ki + k0) * l + k0);
  }
}

// y = x + gamma M x (sphere by sphere, degree by degree).
void SpectralSolver::apply_system(std::span<const double> xs, std::span<double> ys) {
  matvec_M(xs.data(), alpha_.data());
  add_gamma_times(xs.data(), alpha_.data(), ys.data());
}

// y = x + gamma a (a: N ncoef(L) numbers).
void SpectralSolver::add_gamma_times(const double* x, const double* a, double* y) const {
  const int L = L_;
  // sphere by sphere: the same bits at any thread count
#pragma omp parallel for schedule(static) if (std::size_t(N_) * nc_ >= kSpectralParallelLength)
  for (int i = 0; i < N_; ++i) {
    const double* g = &gamma_[i * (L + 1)];
    const double* xi = x + std::size_t(i) * nc_;
    const double* ai = a + std::size_t(i) * nc_;
    double* yi = y + std::size_t(i) * nc_;
    for (int l = 0; l <= L; ++l)
      for (int m = -l; m <= l; ++m) yi[sh::idx(l, m)] = xi[sh::idx(l, m)] + g[l] * ai[sh::idx(l, m)];
  }
}

// beta_ from (I + gamma M) beta = rhs: exact (beta = rhs) when no sphere is polarisable, else GMRES
// to `tol` warm-started from the previous solve (same number of spheres).
GmresResult SpectralSolver::solve_multipoles(const Problem& p, const LargeVector& rhs, double tol) {
  const int N = N_;
  const std::size_t n = std::size_t(N) * nc_;
  if (prev_N_ == N && prev_L_ >= 0) {
    beta_.assign(n, 0.0);
    int Lc = std::min(prev_L_, L_);
    int ncp = sh::ncoef(prev_L_);
    for (int i = 0; i < N; ++i)
      for (int c = 0; c < sh::ncoef(Lc); ++c) beta_[std::size_t(i) * nc_ + c] = prev_beta_[std::size_t(i) * ncp + c];
  } else {
    beta_ = rhs;
  }
  alpha_.resize(n);  // left unset: every product (matvec_M) zeroes it before it adds
  alpha_current_ = false;
  GmresResult gr;
  bool polarisable = false;
  for (const auto& s : p.spheres) polarisable |= (s.permittivity != p.medium_permittivity);
  if (!polarisable) {
    beta_ = rhs;  // no induced multipoles: exact
    gr.converged = true;
    return gr;
  }
  // Euclidean inner product. The explicit residual after the last cycle is what this solver has
  // always computed (1 + iterations + 1 operator applications for a single-cycle solve); without
  // it one application per solve is saved but the reported residual is the Givens estimate.
  const GmresOptions go{tol, opt_.max_iterations, std::min(opt_.max_iterations, 60), true};
  if (pc_coarse_ || pc_pair_ || pc_contact_ || pc_contact_low_) {
    // right preconditioning: A P^-1 u = rhs, beta = P^-1 u; the residual is the true one, rhs - A beta.
    // The last application (GMRES's explicit residual at its solution) leaves z_ = P^-1 u = beta.
    const bool warm = prev_N_ == N && prev_L_ >= 0;
    if (warm && pc_contact_low_) {
      gr = solve_warm_shifted(rhs, go);
    } else {
      LargeVector u(n);
      if (warm)
        precondition_forward(beta_.data(), u.data());
      else
        u = rhs;
      z_.resize(n);
      auto apply_pc = [&](std::span<const double> us, std::span<double> ys) {
        precondition(us.data(), z_.data());
        apply_system(z_, ys);
      };
      gr = pc_contact_low_ ? solve_kept(rhs, u, go) : gmres(apply_pc, rhs, u, {}, go, &ws_);
      beta_ = z_;
    }
  } else {
    auto apply = [&](std::span<const double> xs, std::span<double> ys) { apply_system(xs, ys); };
    gr = gmres(apply, rhs, beta_, {}, go, &ws_);
  }
  if (!gr.converged)
    throw NumericalError(fmt::format(
        "spectral: GMRES did not converge in {} iterations (relative residual {:.3g} > {:.3g}); raise "
        "{} or check the configuration",
        gr.iterations, gr.residual, tol, solver_keys().max_iterations.dotted()));
  // A converged GMRES (recheck_true_residual) ends with the explicit residual of its solution, beta_:
  // its application left alpha_ = M beta_ (apply_system).
  alpha_current_ = true;
  return gr;
}

// contact_low's warm start, exact: A P^-1 w = rhs - A beta_prev from w = 0, beta = beta_prev + P^-1 w
// (its P^-1 = I - X + X^2 has no cheap inverse for the guess u = P beta_prev: (I + X) beta_prev started
// GMRES from (I + X^3) beta_prev). The stopping rule stays ||rhs - A beta|| <= tol ||rhs||, and on return
// alpha_ = M beta = M beta_prev + M P^-1 w (the last application's). An application to w = 0 (GMRES's first
// residual) is 0 without a product. Element-wise passes only: the same bits at any thread count.
GmresResult SpectralSolver::solve_warm_shifted(const LargeVector& rhs, const GmresOptions& go) {
  const std::size_t n = rhs.size();
  const bool threaded = n >= kSpectralParallelLength;
  LargeVector b(n), w(n), alpha0;
  apply_system(beta_, b);  // b = A beta_prev, alpha_ = M beta_prev
  alpha0 = alpha_;
  double rn = 0.0, bn = 0.0;  // sequential sums: the same bits at any thread count
#pragma omp parallel for schedule(static) if (threaded)
  for (std::size_t c = 0; c < n; ++c) b[c] = rhs[c] - b[c];
  for (std::size_t c = 0; c < n; ++c) {
    rn += rhs[c] * rhs[c];
    bn += b[c] * b[c];
  }
  std::fill(w.begin(), w.end(), 0.0);
  z_.resize(n);
  GmresOptions g = go;
  if (bn > 0.0) g.tolerance = go.tolerance * std::sqrt(rn / bn);
  GmresResult gr = solve_kept(b, w, g);
  if (rn > 0.0) gr.residual *= std::sqrt(bn / rn);
#pragma omp parallel for schedule(static) if (threaded)
  for (std::size_t c = 0; c < n; ++c) {
    beta_[c] += z_[c];
    alpha_[c] += alpha0[c];
  }
  return gr;
}

// contact_low (P^-1 = I - X + X^2 - ..., linear): GMRES on A P^-1 u = b from u, keeping M P^-1 v of every
// vector v it applies the operator to (kept_: the cycle's start u_0, then V(0), V(1), ...). When GMRES's
// Givens estimate has converged, u = u_0 + sum_i y_i V(i), so M P^-1 u is the same combination of the kept
// products: alpha_ from it, z_ = P^-1 u from one preconditioner pass, and the explicit residual
// ||b - (z_ + gamma alpha_)|| <= tol ||b|| checked (close_kept): 1 + iterations products instead of GMRES's
// 2 + iterations. If that check fails, or more than kKeptProducts basis vectors were applied, GMRES with
// its own explicit residual continues from u. On return z_ = P^-1 u and alpha_ = M z_ (to rounding); a
// start at u = 0 costs no product (the application to 0 is 0). Element-wise passes and per-sphere sums
// added in sphere order: the same bits at any thread count.
GmresResult SpectralSolver::solve_kept(const LargeVector& b, LargeVector& u, const GmresOptions& go) {
  const std::size_t n = b.size();
  if (kept_.capacity() < std::size_t(kKeptProducts + 1) * n) {
    kept_.clear();
    kept_.reserve(std::size_t(kKeptProducts + 1) * n);
  }
  kept_closed_ = false;
  std::ptrdiff_t last = -1;  // kept slot of the last application
  auto apply = [&](std::span<const double> us, std::span<double> ys) {
    const std::ptrdiff_t slot = us.data() == u.data() ? 0 : (us.data() - ws_.V.data()) / std::ptrdiff_t(n) + 1;
    last = slot <= kKeptProducts ? slot : -1;
    double* a = alpha_.data();
    if (last >= 0) {
      kept_.resize(std::max(kept_.size(), std::size_t(slot + 1) * n));
      a = kept_.data() + std::size_t(slot) * n;
    }
    if (slot == 0 && std::all_of(us.begin(), us.end(), [](double v) { return v == 0.0; })) {
      std::fill(z_.begin(), z_.end(), 0.0);
      std::fill(a, a + n, 0.0);
      std::fill(ys.begin(), ys.end(), 0.0);
      return;
    }
    precondition(us.data(), z_.data());
    matvec_M(z_.data(), a);
    add_gamma_times(z_.data(), a, ys.data());
  };
  GmresOptions once = go;
  once.recheck_true_residual = false;
  GmresResult gr = gmres(apply, b, u, {}, once, &ws_);
  if (gr.matvecs == 0) {  // b = 0: u = 0 without an application
    z_.assign(n, 0.0);
    alpha_.assign(n, 0.0);
    return gr;
  }
  if (gr.converged && last == 0) {  // GMRES's explicit residual at u: z_, kept slot 0 are P^-1 u, M P^-1 u
    std::copy(kept_.begin(), kept_.begin() + std::ptrdiff_t(n), alpha_.begin());
    kept_closed_ = true;
    return gr;
  }
  kept_closed_ = gr.converged && last == std::ptrdiff_t(ws_.y.size()) && close_kept(b, u, go.tolerance, gr.residual);
  if (kept_closed_) return gr;
  GmresOptions rest = go;
  rest.max_iterations = std::max(0, go.max_iterations - gr.iterations);
  auto plain = [&](std::span<const double> us, std::span<double> ys) {
    precondition(us.data(), z_.data());
    apply_system(z_, ys);
  };
  const GmresResult more = gmres(plain, b, u, {}, rest, &ws_);
  gr.iterations += more.iterations;
  gr.matvecs += more.matvecs;
  gr.residual = more.residual;
  gr.converged = more.converged;
  return gr;
}

// solve_kept's close: alpha_ = kept start + sum_i y_i kept V(i) (each number alone, the terms in GMRES's
// order), z_ = P^-1 u, and the relative explicit residual of b - (z_ + gamma alpha_) (per sphere, the
// spheres' sums added in sphere order); whether it is <= tol.
bool SpectralSolver::close_kept(const LargeVector& b, const LargeVector& u, double tol, double& residual) {
  const std::size_t n = b.size();
  const std::vector<double>& y = ws_.y;
  const double* kp = kept_.data();
  alpha_.resize(n);
#pragma omp parallel for schedule(static) if (n >= kSpectralParallelLength)
  for (std::size_t j = 0; j < n; ++j) {
    double a = kp[j];
    for (std::size_t i = 0; i < y.size(); ++i) a += y[i] * kp[(i + 1) * n + j];
    alpha_[j] = a;
  }
  precondition(u.data(), z_.data());
  std::vector<double> rr(static_cast<std::size_t>(N_)), bb(static_cast<std::size_t>(N_));
  const std::size_t nc = std::size_t(nc_);
#pragma omp parallel for schedule(static) if (n >= kSpectralParallelLength)
  for (int i = 0; i < N_; ++i) {
    const double* g = &gamma_[std::size_t(i) * (L_ + 1)];
    double r2 = 0.0, b2 = 0.0;
    for (int l = 0; l <= L_; ++l)
      for (int m = -l; m <= l; ++m) {
        const std::size_t c = std::size_t(i) * nc + std::size_t(sh::idx(l, m));
        const double r = b[c] - (z_[c] + g[l] * alpha_[c]);
        r2 += r * r;
        b2 += b[c] * b[c];
      }
    rr[std::size_t(i)] = r2;
    bb[std::size_t(i)] = b2;
  }
  double r2 = 0.0, b2 = 0.0;
  for (int i = 0; i < N_; ++i) {
    r2 += rr[std::size_t(i)];
    b2 += bb[std::size_t(i)];
  }
  residual = b2 > 0.0 ? std::sqrt(r2 / b2) : 0.0;
  return std::sqrt(r2) <= tol * std::sqrt(b2);
}

// Forces, torques (closed forms of spectral_solver.hpp) and energy from beta_ and alpha_ (the
// complete external potential coefficients). Sphere by sphere, in parallel from kSpectralParallelLength
// unknowns on: each sphere's numbers are computed alone and the energy terms are added in sphere order
// afterwards, so the bits do not depend on the thread count.
Solution SpectralSolver::forces_and_energy(const Problem& p) const {
  const int N = N_, L = L_;
  const double k0 = p.medium_permittivity;
  Solution sol;
  sol.force.assign(N, Vec3{});
  sol.torque.assign(N, Vec3{});
  std::vector<double> energy(N);
#pragma omp parallel if (std::size_t(N) * nc_ >= kSpectralParallelLength)
  {
    std::vector<double> gx(nc_), gy(nc_), gz(nc_);
#pragma omp for schedule(static)
    for (int i = 0; i < N; ++i) {
      const auto& s = p.spheres[i];
      const double* al = &alpha_[std::size_t(i) * nc_];
      const double* be = &beta_[std::size_t(i) * nc_];
      // F = -kappa0 grad_shift \int sigma phi_ext dS = -kappa0 4 pi eps0 sum w_m beta (a grad phi)_lm
      sh::gradient(L, al, gx.data(), gy.data(), gz.data());
      auto wdot = [&](const std::vector<double>& g) {
        double acc = 0.0;
        for (int l = 0; l <= L; ++l)
          for (int m = -l; m <= l; ++m) acc += (m == 0 ? 1.0 : 0.5) * be[sh::idx(l, m)] * g[sh::idx(l, m)];
        return acc;
      };
      const double c = -k0 * 4 * pi * eps0;
      sol.force[i] = Vec3{wdot(gx), wdot(gy), wdot(gz)} * c;
      // M = kappa0 \int sigma r x E = -kappa0 4 pi eps0 a sum w_m beta (r x grad) alpha
      sh::rotation_generator(L, al, gx.data(), gy.data(), gz.data());
      sol.torque[i] = Vec3{wdot(gx), wdot(gy), wdot(gz)} * (c * s.radius);
      energy[i] = 0.5 * s.charge * (be[0] + al[0]);
    }
  }
  double U = 0.0;
  for (int i = 0; i < N; ++i) U += energy[i];
  sol.energy = U;
  return sol;
}

Solution SpectralSolver::solve(const Problem& p) {
  auto t0 = std::chrono::steady_clock::now();
  validate_spheres(p);
  const int N = static_cast<int>(p.spheres.size());
  inner_iterations_ = 0;
  double est_err = 0.0;
  const int L = choose_degree(p, est_err);
  prepare(p, L);
  LargeVector alpha_ext, rhs;
  applied_field(p, alpha_ext, rhs);
  const double tol = std::min(opt_.tolerance, 1e-2 * opt_.target_accuracy);
  const GmresResult gr = solve_multipoles(p, rhs, tol);
  // external potential coefficients (M beta_ is there after GMRES; one product less per solve)
  parallel_blocks_ = std::count_if(blocks_.begin(), blocks_.end(), [](const PairBlock& b) { return b.parallel; });
  if (!alpha_current_) matvec_M(beta_.data(), alpha_.data());
  const std::size_t nall = alpha_.size();
#pragma omp parallel for schedule(static) if (nall >= kSpectralParallelLength)
  for (std::size_t c = 0; c < nall; ++c) alpha_[c] += alpha_ext[c];
  Solution sol = forces_and_energy(p);

  prev_beta_ = beta_;
  prev_L_ = L;
  prev_N_ = N;
  last_ = p;
  sol.stats.iterations = gr.iterations;
  sol.stats.residual = gr.residual;
  sol.stats.degree = L;
  sol.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  int maxpair = 0, maxorder = 0;
  for (const auto& pr : pairs_) {
    maxpair = std::max(maxpair, pr.L);
    maxorder = std::max(maxorder, pr.M);
  }
  sol.stats.extra = {{"estimated_relative_error", est_err},
                     {"degree_capped", opt_.max_degree <= 0 && L >= opt_.max_degree_limit},
                     {"max_pair_degree", maxpair},
                     {"max_pair_order", maxorder},
                     {"gmres_tolerance", tol},
                     {"parallel_pair_blocks", parallel_blocks_}};
  if (pc_coarse_ || pc_pair_ || pc_contact_ || pc_contact_low_) {
    sol.stats.extra["preconditioner_inner_iterations"] = inner_iterations_;
    sol.stats.extra["matched_pairs"] = matched_.size();
    sol.stats.extra["contact_low_parallel"] = low_parallel_;
    if (pc_contact_low_) sol.stats.extra["closed_from_kept_products"] = kept_closed_;
  }
  if (far_) {
    sol.stats.extra["far_field_order"] = far_->order();
    sol.stats.extra["near_pairs"] = pairs_.size();
    sol.stats.extra["m2l"] = far_->m2l_count();
    sol.stats.extra["far_field_parallel"] = far_->parallel();
    sol.stats.extra["pivot_pairs"] = std::count_if(pairs_.begin(), pairs_.end(), [](const Pair& q) { return q.pivot; });
  }
  return sol;
}

// Degree, far field (far_field = "fmm") and pairs for problem p at degree L.
void SpectralSolver::prepare(const Problem& p, int L) {
  L_ = L;
  N_ = static_cast<int>(p.spheres.size());
  nc_ = sh::ncoef(L);
  if (L > T_.degree()) T_.prepare(std::max(L, std::min(opt_.max_degree_limit, L + 8)));  // grows only
  far_.reset();
  if (opt_.far_field == kFarFieldNames[1]) {
    far_ = std::make_unique<sh::SphereFarField>(p, L, far_options_);
    if (!far_options_.stored_rotations && pivot_.degree() != L) pivot_.build(L);
  }
  build_pairs(p);
  index_blocks();
  prepare_preconditioner(p);
}

// The preconditioner's set-up: the coarse system (a solver at degree kCoarseDegree with its gamma), or
// the matching of the close pairs (pairs of degree >= kPivotDegree, closest gap first, greedy); the
// contact network needs none (the close pairs are those of pairs_ of degree >= kPivotDegree).
void SpectralSolver::prepare_preconditioner(const Problem& p) {
  const std::string& name = opt_.preconditioner;
  pc_coarse_ = name == kPreconditionerNames[1];
  pc_pair_ = name == kPreconditionerNames[2];
  pc_contact_ = name == kPreconditionerNames[3];
  pc_contact_low_ = name == kPreconditionerNames[4];
  coarse_.reset();
  matched_.clear();
  low_pairs_.clear();
  low_parallel_ = false;
  if (pc_contact_low_) build_contact_low(p);
  if (pc_coarse_ && L_ > kCoarseDegree) {
    SolverOptions oc = opt_;
    oc.max_degree = kCoarseDegree;
    oc.preconditioner = kPreconditionerNames[0];
    coarse_ = std::make_unique<SpectralSolver>(oc, far_options_);
    coarse_->prepare(p, kCoarseDegree);
    coarse_->set_gamma(p);
    coarse_->alpha_.resize(std::size_t(N_) * coarse_->nc_);
  }
  if (pc_pair_) {
    std::vector<std::pair<double, std::size_t>> cand;
    for (std::size_t q = 0; q < pairs_.size(); ++q) {
      const Pair& pr = pairs_[q];
      if (pr.L < kPivotDegree) continue;
      const auto& a = p.spheres[pr.i];
      const auto& b = p.spheres[pr.k];
      const double gap = norm(b.center - a.center) - a.radius - b.radius;
      cand.emplace_back(gap / std::min(a.radius, b.radius), q);
    }
    std::sort(cand.begin(), cand.end());
    std::vector<char> used(N_, 0);
    for (const auto& [g, q] : cand) {
      const Pair& pr = pairs_[q];
      if (used[pr.i] || used[pr.k]) continue;
      used[pr.i] = used[pr.k] = 1;
      matched_.push_back(q);
    }
  }
}

// z = P^-1 u: the contact network's system solved, or the matched pairs' two-sphere systems (block
// Jacobi), or the degrees <= kCoarseDegree replaced by the coarse system's solution for u's low degrees.
void SpectralSolver::precondition(const double* u, double* z) {
  const std::ptrdiff_t n = std::ptrdiff_t(N_) * nc_;
#pragma omp parallel for schedule(static) if (std::size_t(n) >= kSpectralParallelLength)
  for (std::ptrdiff_t c = 0; c < n; ++c) z[c] = u[c];
  if (pc_contact_) contact_inverse(u, z);
  const int steps = opt_.contact_low_steps;
  for (int k = 0; pc_contact_low_ && k < steps; ++k) apply_contact_low(z, u, z, -1.0);
  for (std::size_t q : matched_) pair_block_inverse(pairs_[q], u, z);
  if (coarse_) coarse_inverse(u, z);
}

// u = P x for the warm start's guess (coarse, pair, contact; contact_low's warm start is solve_warm_shifted).
void SpectralSolver::precondition_forward(const double* x, double* u) {
  const std::size_t n = std::size_t(N_) * nc_, nc = std::size_t(nc_);
#pragma omp parallel for schedule(static) if (n >= kSpectralParallelLength)
  for (std::size_t c = 0; c < n; ++c) u[c] = x[c];
  if (pc_contact_) {
    std::vector<double> al(n, 0.0);
    add_contact_products(x, al.data());
    add_gamma_times(x, al.data(), u);
  }
  std::vector<double> s(4 * nc), o(2 * nc);
  for (std::size_t q : matched_) {
    const Pair& pr = pairs_[q];
    const int np = sh::ncoef(pr.L);
    pair_product_at(pr, x + pr.i * nc, x + pr.k * nc, o.data(), o.data() + np, s.data());
    const double *gi = &gamma_[pr.i * (L_ + 1)], *gk = &gamma_[pr.k * (L_ + 1)];
    for (int l = 0; l <= pr.L; ++l)
      for (int m = -l; m <= l; ++m) {
        u[pr.i * nc + sh::idx(l, m)] += gi[l] * o[sh::idx(l, m)];
        u[pr.k * nc + sh::idx(l, m)] += gk[l] * o[np + sh::idx(l, m)];
      }
  }
  if (!coarse_) return;
  const int ncc = coarse_->nc_;
  pc_zc_.resize(std::size_t(N_) * ncc);
  pc_uc_.resize(pc_zc_.size());
  for (int i = 0; i < N_; ++i)
    for (int c = 0; c < ncc; ++c) pc_zc_[std::size_t(i) * ncc + c] = x[i * nc + c];
  coarse_->apply_system(pc_zc_, pc_uc_);
  for (int i = 0; i < N_; ++i)
    for (int c = 0; c < ncc; ++c) u[i * nc + c] = pc_uc_[std::size_t(i) * ncc + c];
}

// z's degrees <= the coarse degree: the solution of the coarse system for u's (inner GMRES to kInnerTolerance).
void SpectralSolver::coarse_inverse(const double* u, double* z) {
  const int ncc = coarse_->nc_;
  const std::size_t nc = std::size_t(nc_);
  pc_uc_.resize(std::size_t(N_) * ncc);
  for (int i = 0; i < N_; ++i)
    for (int c = 0; c < ncc; ++c) pc_uc_[std::size_t(i) * ncc + c] = u[i * nc + c];
  pc_zc_ = pc_uc_;
  auto apply = [&](std::span<const double> xs, std::span<double> ys) { coarse_->apply_system(xs, ys); };
  const GmresResult r = gmres(apply, pc_uc_, pc_zc_, {}, GmresOptions{kInnerTolerance, 1000, 200, true});
  inner_iterations_ += r.iterations;
  for (int i = 0; i < N_; ++i)
    for (int c = 0; c < ncc; ++c) z[i * nc + c] = pc_zc_[std::size_t(i) * ncc + c];
}

// contact_low: each close pair (degree >= kPivotDegree) again at degree kContactLowDegree and frame order
// kContactLowOrder, with its own stored rotation blocks (small at that degree and order).
// The pairs are set up in parallel (each alone: the same numbers at any thread count).
void SpectralSolver::build_contact_low(const Problem& p) {
  std::vector<std::size_t> close;
  for (std::size_t q = 0; q < pairs_.size(); ++q)
    if (pairs_[q].L >= kPivotDegree) close.push_back(q);
  low_pairs_.resize(close.size());
  low_parallel_ = double(close.size()) * std::pow(kContactLowDegree + 1.0, 3) > kParallelPairWork;
#pragma omp parallel for schedule(dynamic, 16) if (low_parallel_ && omp_get_max_threads() > 1)
  for (std::size_t r = 0; r < close.size(); ++r) {
    const Pair& pr = pairs_[close[r]];
    Pair& q = low_pairs_[r];
    q.i = pr.i;
    q.k = pr.k;
    q.ui = pr.ui;
    q.uk = pr.uk;
    q.L = std::min(pr.L, kContactLowDegree);
    q.M = std::min(pr.M, kContactLowOrder);
    q.R.build(p.spheres[pr.k].center - p.spheres[pr.i].center, q.L, q.M);
    sh::AxialTranslation::source_powers(std::min(q.L, q.M), q.ui, q.uk, q.powers);
  }
  index_contact_low();
}

// low_start_, low_slot_: each sphere's products in low_out_, in pair order (pair r writes its sphere i's
// product at 2 r nl, its sphere k's at (2 r + 1) nl).
void SpectralSolver::index_contact_low() {
  const std::size_t nl = std::size_t(sh::ncoef(kContactLowDegree));
  low_start_.assign(std::size_t(N_) + 1, 0);
  for (const Pair& pr : low_pairs_) {
    ++low_start_[std::size_t(pr.i) + 1];
    ++low_start_[std::size_t(pr.k) + 1];
  }
  for (std::size_t i = 0; i < std::size_t(N_); ++i) low_start_[i + 1] += low_start_[i];
  low_slot_.resize(2 * low_pairs_.size());
  std::vector<std::size_t> next(low_start_.begin(), low_start_.end() - 1);
  for (std::size_t r = 0; r < low_pairs_.size(); ++r) {
    low_slot_[next[std::size_t(low_pairs_[r].i)]++] = 2 * r * nl;
    low_slot_[next[std::size_t(low_pairs_[r].k)]++] = (2 * r + 1) * nl;
  }
  low_out_.resize(2 * low_pairs_.size() * nl);
}

// low_out_: each low pair's two products of x (pair r: sphere i's at 2 r nl, sphere k's at (2 r + 1) nl,
// ncoef(pair degree) numbers each), the pairs in parallel, each into its own slot.
void SpectralSolver::contact_low_products(const double* x) {
  const std::size_t nc = std::size_t(nc_), nl = std::size_t(sh::ncoef(kContactLowDegree));
  const std::size_t npairs = low_pairs_.size();
  const int threads = omp_get_max_threads();
  scratch_.resize(std::max(scratch_.size(), std::size_t(threads) * 4 * nl));
#pragma omp parallel for schedule(dynamic, 16) if (low_parallel_ && threads > 1)
  for (std::size_t r = 0; r < npairs; ++r) {
    const Pair& pr = low_pairs_[r];
    double* o = &low_out_[2 * r * nl];
    pair_product_at(pr, x + pr.i * nc, x + pr.k * nc, o, o + nl,
                    &scratch_[std::size_t(omp_get_thread_num()) * 4 * nl]);
  }
}

// z = u + sign gamma M_low x at degrees 1..kContactLowDegree of the spheres with low pairs (z's other
// numbers are left as they are; z may be x): with sign -1, z = u - gamma M_low x, a Neumann step of the
// low contact system's inverse. Sphere by sphere (in parallel), each
// summing its pair products in pair order: the same bits at any thread count.
void SpectralSolver::apply_contact_low(const double* x, const double* u, double* z, double sign) {
  if (low_pairs_.empty()) return;
  contact_low_products(x);  // reads all of x before z is written
  const std::size_t nc = std::size_t(nc_);
  const int Lc = std::min(L_, kContactLowDegree);
  const int nlc = sh::ncoef(Lc);
#pragma omp parallel if (low_parallel_ && omp_get_max_threads() > 1)
  {
    std::vector<double> acc(static_cast<std::size_t>(nlc));
#pragma omp for schedule(static)
    for (int i = 0; i < N_; ++i) {
      const std::size_t s0 = low_start_[std::size_t(i)], s1 = low_start_[std::size_t(i) + 1];
      if (s0 == s1) continue;
      std::fill(acc.begin(), acc.end(), 0.0);
      for (std::size_t s = s0; s < s1; ++s) {
        const double* o = &low_out_[low_slot_[s]];
        for (int c = 0; c < nlc; ++c) acc[std::size_t(c)] += o[c];
      }
      const double* g = &gamma_[std::size_t(i) * (L_ + 1)];
      const double* ui = u + std::size_t(i) * nc;
      double* zi = z + std::size_t(i) * nc;
      for (int l = 1; l <= Lc; ++l)
        for (int m = -l; m <= l; ++m)
          zi[sh::idx(l, m)] = ui[sh::idx(l, m)] + sign * g[l] * acc[std::size_t(sh::idx(l, m))];
    }
  }
}

// alpha += M_contact x: the products of the close pairs (degree >= kPivotDegree) alone, in pair order.
void SpectralSolver::add_contact_products(const double* x, double* alpha) const {
  const std::size_t nc = std::size_t(nc_);
  std::vector<double> s(4 * nc), o(2 * nc);
  for (const Pair& pr : pairs_) {
    if (pr.L < kPivotDegree) continue;
    const int np = sh::ncoef(pr.L);
    pair_product_at(pr, x + pr.i * nc, x + pr.k * nc, o.data(), o.data() + np, s.data());
    for (int c = 0; c < np; ++c) {
      alpha[pr.i * nc + c] += o[c];
      alpha[pr.k * nc + c] += o[np + c];
    }
  }
}

// z = (I + gamma M_contact)^-1 u (inner GMRES to kInnerTolerance): every close pair at once, the
// contact network's chains included.
void SpectralSolver::contact_inverse(const double* u, double* z) {
  const std::size_t n = std::size_t(N_) * nc_;
  std::vector<double> b(u, u + n), x(u, u + n), al(n);
  auto apply = [&](std::span<const double> xs, std::span<double> ys) {
    std::fill(al.begin(), al.end(), 0.0);
    add_contact_products(xs.data(), al.data());
    add_gamma_times(xs.data(), al.data(), ys.data());
  };
  const GmresResult r = gmres(apply, b, x, {}, GmresOptions{kInnerTolerance, 1000, 200, true});
  inner_iterations_ += r.iterations;
  std::copy(x.begin(), x.end(), z);
}

// z_i, z_k (degrees <= the pair's) from the pair's two-sphere system
//   z_i + gamma_i (M_ik z_k) = u_i,  z_k + gamma_k (M_ki z_i) = u_k  (inner GMRES to kInnerTolerance).
void SpectralSolver::pair_block_inverse(const Pair& pr, const double* u, double* z) {
  const int np = sh::ncoef(pr.L);
  const std::size_t nc = std::size_t(nc_);
  std::vector<double> b(2 * np), x, s(4 * np), o(2 * np);
  std::copy(u + pr.i * nc, u + pr.i * nc + np, b.begin());
  std::copy(u + pr.k * nc, u + pr.k * nc + np, b.begin() + np);
  x = b;
  const double *gi = &gamma_[pr.i * (L_ + 1)], *gk = &gamma_[pr.k * (L_ + 1)];
  auto apply = [&](std::span<const double> xs, std::span<double> ys) {
    pair_product_at(pr, xs.data(), xs.data() + np, o.data(), o.data() + np, s.data());
    for (int l = 0; l <= pr.L; ++l)
      for (int m = -l; m <= l; ++m) {
        ys[sh::idx(l, m)] = xs[sh::idx(l, m)] + gi[l] * o[sh::idx(l, m)];
        ys[np + sh::idx(l, m)] = xs[np + sh::idx(l, m)] + gk[l] * o[np + sh::idx(l, m)];
      }
  };
  const GmresResult r = gmres(apply, b, x, {}, GmresOptions{kInnerTolerance, 1000, 200, true});
  inner_iterations_ += r.iterations;
  std::copy(x.begin(), x.begin() + np, z + pr.i * nc);
  std::copy(x.begin() + np, x.end(), z + pr.k * nc);
}

std::vector<double> SpectralSolver::product(const Problem& p, const std::vector<double>& beta,
                                            const sh::FarFieldOptions* far, int repeat) {
  validate_spheres(p);
  if (far) far_options_ = *far;
  prepare(p, degree(p));
  if (beta.size() != std::size_t(N_) * nc_) throw std::invalid_argument("spectral_product: beta of the wrong size");
  std::vector<double> alpha(beta.size());
  for (int r = 0; r < std::max(1, repeat); ++r) matvec_M(beta.data(), alpha.data());
  return alpha;
}

std::vector<SurfaceSample> SpectralSolver::surface() const {
  std::vector<SurfaceSample> out;
  if (beta_.empty()) return out;
  auto mesh = icosphere(icosphere_level_for(opt_.patches_per_sphere));
  out.reserve(std::size_t(N_) * mesh.vertices.size());
  std::vector<double> y(nc_);
  for (int i = 0; i < N_; ++i) {
    // O(L^2) per vertex: about 70 ms per sphere at degree 69 with 2562 vertices, the longest phase of a
    // 30-sphere solve after GMRES (2 s); a cancelled run stops within one sphere (core/cancel.hpp).
    poll_cancel();
    const auto& s = last_.spheres[i];
    const double* be = &beta_[std::size_t(i) * nc_];
    const double sf = s.charge / (4 * pi * s.radius * s.radius);
    for (const auto& nv : mesh.vertices) {
      sh::eval_surface(L_, nv, y.data());
      // sigma_lm = eps0 (2l+1) B_lm / a^(l+2) = eps0 (2l+1) beta_lm / a
      double sig = 0.0;
      for (int l = 0; l <= L_; ++l) {
        double acc = 0.0;
        for (int m = -l; m <= l; ++m) acc += be[sh::idx(l, m)] * y[sh::idx(l, m)];
        sig += (2 * l + 1) * acc;
      }
      sig *= eps0 / s.radius;
      SurfaceSample ss;
      ss.position = s.center + nv * s.radius;
      ss.normal = nv;
      ss.area = 4 * pi * s.radius * s.radius / mesh.vertices.size();
      ss.sigma_free = sf;
      ss.sigma_bound = sig - sf;
      ss.body = i;
      out.push_back(ss);
    }
  }
  return out;
}

std::vector<std::array<int, 3>> SpectralSolver::surface_triangles() const {
  std::vector<std::array<int, 3>> tri;
  if (beta_.empty()) return tri;
  auto mesh = icosphere(icosphere_level_for(opt_.patches_per_sphere));
  const int nv = static_cast<int>(mesh.vertices.size());
  tri.reserve(std::size_t(N_) * mesh.triangles.size());
  for (int i = 0; i < N_; ++i) {
    poll_cancel();  // millions of triangles for hundreds of spheres at the finest mesh
    for (const auto& t : mesh.triangles) tri.push_back({t[0] + i * nv, t[1] + i * nv, t[2] + i * nv});
  }
  return tri;
}

}  // namespace

std::unique_ptr<Solver> make_spectral_solver(const SolverOptions& opt) {
  return std::make_unique<SpectralSolver>(opt);
}

std::unique_ptr<Solver> make_spectral_solver(const SolverOptions& opt, const sh::FarFieldOptions& far) {
  return std::make_unique<SpectralSolver>(opt, far);
}

double far_field_tolerance(const SolverOptions& opt) { return kFarFieldAccuracy * opt.target_accuracy; }

int spectral_degree(const SolverOptions& opt, const Problem& p) { return SpectralSolver(opt).degree(p); }

std::vector<double> spectral_product(const SolverOptions& opt, const Problem& p, const std::vector<double>& beta,
                                     const sh::FarFieldOptions* far, int repeat) {
  return SpectralSolver(opt).product(p, beta, far, repeat);
}

}  // namespace agglo::es
