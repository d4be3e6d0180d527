// Fast far field of the spectral solver (electrostatics.far_field = "fmm", spectral/far_field.hpp)
// against its twin, the dense product (every pair re-expanded directly).
#include <gtest/gtest.h>

#include <algorithm>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string_view>
#include <tuple>
#include <vector>

#include "agglo/electrostatics/config.hpp"
#include "agglo/electrostatics/estimate.hpp"
#include "agglo/structure/fractal.hpp"
#include "agglo/electrostatics/fmm/solid_harmonics.hpp"
#include "agglo/electrostatics/spectral/complex_basis.hpp"
#include "agglo/electrostatics/spectral/far_field.hpp"
#include "agglo/electrostatics/spectral/harmonics.hpp"
#include "agglo/electrostatics/spectral/spectral_solver.hpp"
#include "es_test_helpers.hpp"

namespace agglo::es {
namespace {

using testing::kQ0;
using testing::kR;

// A random connected cluster: each new sphere (radius r, or uniform in [r, ratio r]) is put at a random
// direction from a random earlier one, at a gap 0.01 r (every third sphere) or uniform in [0.01, 1] r,
// and kept when it clears every other sphere by 0.01 r. Charges alternate +-kQ0 (neutral total for
// even N); permittivity kappa.
Problem random_cluster(int n, double ratio, double kappa, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Problem p;
  auto radius = [&] { return kR * (ratio == 1.0 ? 1.0 : 1.0 + (ratio - 1.0) * u(rng)); };
  p.spheres.push_back({Vec3{}, radius(), kQ0, kappa});
  while (static_cast<int>(p.spheres.size()) < n) {
    const auto& base = p.spheres[std::size_t(u(rng) * p.spheres.size())];
    const double r = radius();
    const double gap = (p.spheres.size() % 3 == 0 ? 0.01 : 0.01 + 0.99 * u(rng)) * kR;
    const double z = 2 * u(rng) - 1, phi = 2 * constants::pi * u(rng), s = std::sqrt(1 - z * z);
    const Vec3 c = base.center + (base.radius + r + gap) * Vec3{s * std::cos(phi), s * std::sin(phi), z};
    bool clear = true;
    for (const auto& o : p.spheres) clear = clear && norm(o.center - c) >= o.radius + r + 0.01 * kR * 0.999;
    if (!clear) continue;
    const double q = (p.spheres.size() % 2 == 0 ? 1.0 : -1.0) * kQ0;
    p.spheres.push_back({c, r, q, kappa});
  }
  return p;
}

SolverOptions far_field_options(const std::string& far_field) {
  SolverOptions o;
  o.far_field = far_field;
  return o;
}

// Random multipoles, O(1) at every degree (the hardest input for a truncated far field).
std::vector<double> random_beta(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> b(n);
  for (auto& v : b) v = u(rng);
  return b;
}

double relative_difference(const std::vector<double>& a, const std::vector<double>& ref) {
  double d = 0.0, r = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    d += (a[k] - ref[k]) * (a[k] - ref[k]);
    r += ref[k] * ref[k];
  }
  return std::sqrt(d / r);
}

// max_k |F_k - G_k| / max_k |G_k|
double force_difference(const Solution& a, const Solution& ref) {
  double d = 0.0, r = 0.0;
  for (std::size_t k = 0; k < a.force.size(); ++k) {
    d = std::max(d, norm(a.force[k] - ref.force[k]));
    r = std::max(r, norm(ref.force[k]));
  }
  return d / r;
}

// Product error of the fast far field against the dense twin (far: options replacing the far field's).
double product_error(const Problem& p, const std::vector<double>& beta, const sh::FarFieldOptions* far = nullptr) {
  const SolverOptions dense = far_field_options("dense"), fast = far_field_options("fmm");
  return relative_difference(spectral_product(fast, p, beta, far), spectral_product(dense, p, beta));
}

// The fmm solve and the dense solve, each cold.
struct TwinSolves {
  Solution fast, dense;
  std::vector<double> beta;  // the fmm solution's multipoles
};
TwinSolves twin_solves(const Problem& p) {
  TwinSolves t;
  auto f = make_solver(far_field_options("fmm"));
  t.fast = f->solve(p);
  t.dense = make_solver(far_field_options("dense"))->solve(p);
  t.beta = f->warm_start().values;
  return t;
}

TEST(ComplexBasis, MultipoleAndLocalMatchTheRealHarmonics) {
  const int p = 12;
  const sh::ComplexBasis basis(p);
  const auto beta = random_beta(sh::ncoef(p), 3);
  const double rho = 0.7;
  std::vector<fmm::cplx> M(fmm::tri_size(p)), I(fmm::tri_size(p)), R(fmm::tri_size(p));
  std::vector<double> y(sh::ncoef(p));
  basis.multipole_from_real(p, rho, beta.data(), M.data());
  const Vec3 x{1.3, -2.1, 0.8};
  fmm::irregular_harmonics(x, p, I.data());
  sh::eval_irregular(p, x, y.data());
  double phi_real = 0.0, phi_complex = 0.0, rn = rho;
  for (int n = 0; n <= p; ++n, rn *= rho)
    for (int m = -n; m <= n; ++m) {
      phi_real += rn * beta[sh::idx(n, m)] * y[sh::idx(n, m)];
      phi_complex += (m == 0 ? 1.0 : 2.0) * (m >= 0 ? (M[fmm::tri(n, m)] * I[fmm::tri(n, m)]).real() : 0.0);
    }
  EXPECT_NEAR(phi_complex, phi_real, 1e-12 * std::abs(phi_real));
  // local: phi = sum_{|m|<=n} L R (L from the same numbers) against the real coefficients it gives
  std::vector<double> alpha(sh::ncoef(p), 0.0);
  basis.add_real_local(p, rho, M.data(), alpha.data());
  fmm::regular_harmonics(x, p, R.data());
  sh::eval_regular(p, x, y.data());
  phi_real = phi_complex = 0.0;
  double rinv = 1.0;
  for (int n = 0; n <= p; ++n, rinv /= rho)
    for (int m = -n; m <= n; ++m) {
      phi_real += rinv * alpha[sh::idx(n, m)] * y[sh::idx(n, m)];
      phi_complex += (m == 0 ? 1.0 : 2.0) * (m >= 0 ? (M[fmm::tri(n, m)] * R[fmm::tri(n, m)]).real() : 0.0);
    }
  EXPECT_NEAR(phi_complex, phi_real, 1e-12 * std::abs(phi_real));
}

struct ClusterCase {
  int n;
  double ratio;
};

class FarFieldTwin : public ::testing::TestWithParam<ClusterCase> {};

// Product and forces of the fast far field within the stated tolerance of the dense twin (both solves
// cold): product (relative 2-norm, the solution's multipoles) <= far_field_tolerance = 0.1
// target_accuracy = 1e-5, forces (largest difference over the largest force) <= 1e-5, GMRES iterations
// equal within 1. Measured (product / forces): N = 50 mono 7.4e-7 / 1.8e-7, N = 200 mono 6.4e-6 / 4.2e-6,
// N = 50 ratio 3 9.3e-7 / 2.3e-7, N = 150 ratio 3 2.9e-6 / 3.2e-6 (N = 150: the ratio-3 cluster needs
// L = 80 and N = 200 took 6 s); 8 iterations each.
TEST_P(FarFieldTwin, ProductAndForcesWithinTheStatedTolerance) {
  const auto [n, ratio] = GetParam();
  const Problem p = random_cluster(n, ratio, 2.5, 11);
  const TwinSolves t = twin_solves(p);
  const double tol = far_field_tolerance(far_field_options("fmm"));
  ASSERT_EQ(tol, 1e-5);
  EXPECT_GT(t.fast.stats.extra.at("m2l").get<int>(), 0) << "no pair went through the octree";
  const double product = product_error(p, t.beta), force = force_difference(t.fast, t.dense);
  std::printf("N = %d, radius ratio %g: product %.2e, forces %.2e, GMRES iterations fmm %d dense %d\n", n, ratio,
              product, force, t.fast.stats.iterations, t.dense.stats.iterations);
  EXPECT_LE(product, tol);
  EXPECT_LE(force, tol);
  EXPECT_LE(std::abs(t.fast.stats.iterations - t.dense.stats.iterations), 1);
}

INSTANTIATE_TEST_SUITE_P(Clusters, FarFieldTwin,
                         ::testing::Values(ClusterCase{50, 1.0}, ClusterCase{200, 1.0}, ClusterCase{50, 3.0},
                                           ClusterCase{150, 3.0}),
                         [](const auto& info) {
                           return "N" + std::to_string(info.param.n) + (info.param.ratio == 1.0 ? "_mono" : "_poly3");
                         });

// An isolated system of neutral total charge (alternating +-Q0, N = 200): sum F ~ 0.
TEST(SpectralFarField, ActionReactionAtN200) {
  const Problem p = random_cluster(200, 1.0, 2.5, 5);
  auto s = make_solver(far_field_options("fmm"));
  const Solution sol = s->solve(p);
  Vec3 sum;
  double largest = 0.0;
  for (const auto& f : sol.force) {
    sum += f;
    largest = std::max(largest, norm(f));
  }
  std::printf("|sum F| / max |F| = %.2e\n", norm(sum) / largest);
  testing::expect_newton_third_law(sol, 1e-5);
}

// F = -dU/dx with the fast far field at N = 200 (issue 25): the force on three spheres (largest, median
// and smallest |F| of the cluster's first 50, one axis each) against central differences of the energy,
// step 1e-4 r, GMRES to 1e-10 so that the solve's own error is smooth in the position. Bound 0.1
// target_accuracy max |F| (measured 1.3e-7 to 2.3e-7 of max |F|). Negative control: the same difference
// against the force on another sphere is far off (the check is not vacuous).
TEST(SpectralFarField, ForceIsMinusEnergyGradientAtN200) {
  const Problem p = random_cluster(200, 1.0, 2.5, 5);
  SolverOptions o = far_field_options("fmm");
  o.tolerance = 1e-10;
  auto s = make_solver(o);
  const Solution sol = s->solve(p);
  double largest = 0.0;
  for (const auto& f : sol.force) largest = std::max(largest, norm(f));
  std::vector<int> order(50);
  for (int k = 0; k < 50; ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return norm(sol.force[a]) > norm(sol.force[b]); });
  const int bodies[3] = {order[0], order[25], order[49]};
  for (int m = 0; m < 3; ++m) {
    const int body = bodies[m], axis = m;
    const auto [force, gradient] = testing::force_and_energy_gradient(*s, p, body, axis, 1e-4 * kR);
    std::printf("sphere %d axis %d: F = %.6e N, -dU/dx = %.6e N (difference %.2e of max |F|)\n", body, axis, force,
                gradient, std::abs(force - gradient) / largest);
    EXPECT_LE(std::abs(force - gradient), 0.1 * o.target_accuracy * largest) << "sphere " << body;
    const int other = bodies[(m + 1) % 3];
    EXPECT_GT(std::abs(sol.force[other][axis] - gradient), 10 * std::abs(force - gradient)) << "negative control";
  }
}

// The existing references through the fast path (issue 25): the two-sphere table of docs/model.md §B.4
// (gaps >= 0.1 r, target 1e-6, as SpectralTable.GapsAtLeastPointOneWithinOneInAMillion for the dense
// product) and the seed's charged square (four spheres at the regularised contact, charges alternating
// +-sigma 4 pi r^2 with sigma = 10 uC/m^2 around the ring, kappa_p = 2.5 and 15) against the dense product.
// With at most 8 spheres the octree is one leaf and every pair is a near pair, so the fast path must give
// the dense forces up to rounding (its quarter turns replace the stored rotation blocks).
TEST(SpectralFarField, ExistingReferencesThroughTheFastPath) {
  SolverOptions o = far_field_options("fmm");
  o.target_accuracy = 1e-6;
  auto s = make_solver(o);
  for (const auto& e : testing::model_b4_table()) {
    if (e.h < 0.1) continue;
    const double f = testing::table_force(*s, e.kappa, e.h, e.c1, e.c2);
    EXPECT_NEAR(f, e.value, 1e-6 * std::abs(e.value) + testing::table_rounding(e.value))
        << "kappa " << e.kappa << " h " << e.h << " (" << e.c1 << "," << e.c2 << ")";
  }
  for (double kappa : {2.5, 15.0}) {
    Problem p;
    const double r = kR / (1.0 + 0.5 * 0.01), q = 10e-6 * 4 * constants::pi * kR * kR;  // min_gap 0.01
    const Vec3 corners[4] = {{-kR, -kR, 0.0}, {kR, -kR, 0.0}, {kR, kR, 0.0}, {-kR, kR, 0.0}};
    for (int k = 0; k < 4; ++k) p.spheres.push_back({corners[k], r, k % 2 == 0 ? q : -q, kappa});
    const Solution fast = make_solver(far_field_options("fmm"))->solve(p);
    const Solution dense = make_solver(far_field_options("dense"))->solve(p);
    const double d = force_difference(fast, dense);
    std::printf("charged square, kappa_p %g: forces fmm vs dense %.2e, energy %.2e\n", kappa, d,
                std::abs(fast.energy - dense.energy) / std::abs(dense.energy));
    EXPECT_LE(d, 1e-10);
    EXPECT_LE(std::abs(fast.energy - dense.energy), 1e-10 * std::abs(dense.energy));
    EXPECT_GT(norm(dense.force[0]), 0.0);
  }
}

// GMRES iterations with the fast far field do not grow with N (target 1e-3 to keep the test short).
TEST(SpectralFarField, GmresIterationsDoNotGrowWithN) {
  SolverOptions o = far_field_options("fmm");
  o.target_accuracy = 1e-3;
  std::vector<int> its;
  for (int n : {100, 300}) {
    auto s = make_solver(o);
    its.push_back(s->solve(random_cluster(n, 1.0, 2.5, 3)).stats.iterations);
  }
  std::printf("GMRES iterations N = 100: %d, N = 300: %d\n", its[0], its[1]);
  EXPECT_LE(std::abs(its[1] - its[0]), 2) << its[0] << " vs " << its[1];
}

// Cold solves of p on one and on two threads: {one thread, two threads}.
std::pair<Solution, Solution> solve_on_one_and_two_threads(const SolverOptions& o, const Problem& p) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  Solution one = make_solver(o)->solve(p);
  omp_set_num_threads(2);
  Solution two = make_solver(o)->solve(p);
  omp_set_num_threads(saved);
  return {std::move(one), std::move(two)};
}

// The same energy, forces and torques, bit for bit, and the same GMRES iterations.
void expect_same_bits(const Solution& two, const Solution& one) {
  EXPECT_EQ(two.stats.iterations, one.stats.iterations);
  EXPECT_EQ(two.energy, one.energy);
  for (std::size_t i = 0; i < one.force.size(); ++i) {
    EXPECT_TRUE(two.force[i].x == one.force[i].x && two.force[i].y == one.force[i].y &&
                two.force[i].z == one.force[i].z)
        << "force on sphere " << i;
    EXPECT_TRUE(two.torque[i].x == one.torque[i].x && two.torque[i].y == one.torque[i].y &&
                two.torque[i].z == one.torque[i].z)
        << "torque on sphere " << i;
  }
}

// The fmm solution is the same at any thread count (bit for bit), with the far-field passes and the pair
// products in parallel and near pairs through the quarter turns (pivot_rotation.hpp).
TEST(SpectralFarField, SolutionDoesNotDependOnTheThreadCount) {
  const SolverOptions o = far_field_options("fmm");  // target 1e-4: L = 47, enough pair work for threads
  const Problem p = random_cluster(300, 1.0, 2.5, 3);
  const auto [one, two] = solve_on_one_and_two_threads(o, p);
  EXPECT_TRUE(two.stats.extra.at("far_field_parallel").get<bool>()) << "the far field ran serially";
  EXPECT_GT(two.stats.extra.at("parallel_pair_blocks").get<int>(), 0) << "the pair products ran serially";
  EXPECT_GT(two.stats.extra.at("pivot_pairs").get<int>(), 0) << "no pair took the quarter turns";
  expect_same_bits(two, one);
}

// The product alpha = M beta (random multipoles) is the same, bit for bit, on 1, 2 and 3 threads (N = 300:
// the near pairs' blocks of mixed degrees, each block's pairs taken largest first from a dynamic schedule
// and its spheres' sums shared out dynamically, matvec_M). Not vacuous: the same pairs run their blocks in
// parallel (the solve's parallel_pair_blocks > 0; the dense twin's blocks of this cluster would not).
TEST(SpectralFarField, ProductDoesNotDependOnTheThreadCount) {
  {
    const char* far_field = "fmm";
    const int n = 300;
    const SolverOptions o = far_field_options(far_field);
    const Problem p = random_cluster(n, 1.0, 2.5, 3);
    const int L = spectral_degree(o, p);
    const std::vector<double> beta = random_beta(std::size_t(n) * (L + 1) * (L + 1), 7);
    const int saved = omp_get_max_threads();
    std::vector<std::vector<double>> alpha;
    for (int threads : {1, 2, 3}) {
      omp_set_num_threads(threads);
      alpha.push_back(spectral_product(o, p, beta));
    }
    const Solution two = make_solver(o)->solve(p);  // still 3 threads
    omp_set_num_threads(saved);
    EXPECT_GT(two.stats.extra.at("parallel_pair_blocks").get<int>(), 0) << far_field << ": blocks ran serially";
    for (std::size_t t = 1; t < alpha.size(); ++t) {
      std::size_t differ = 0;
      for (std::size_t c = 0; c < beta.size(); ++c) differ += alpha[t][c] != alpha[0][c];
      EXPECT_EQ(differ, 0u) << far_field << ": " << t + 1 << " threads against 1";
    }
  }
}

// The contact_low preconditioner's passes (the low pairs' products, then sphere by sphere their sums in
// pair order) run in parallel and give the same bits on one and two threads (kappa_p = 15, the N = 300
// cluster: about a hundred close pairs, enough work for threads).
TEST(SpectralPreconditioner, ContactLowDoesNotDependOnTheThreadCount) {
  SolverOptions o = far_field_options("fmm");
  o.preconditioner = "contact_low";
  const Problem p = random_cluster(300, 1.0, 15.0, 3);
  const auto [one, two] = solve_on_one_and_two_threads(o, p);
  EXPECT_TRUE(two.stats.extra.at("contact_low_parallel").get<bool>()) << "the contact_low passes ran serially";
  EXPECT_TRUE(two.stats.extra.at("closed_from_kept_products").get<bool>()) << "the cold solve took a product more";
  EXPECT_GT(two.stats.iterations, 0);
  expect_same_bits(two, one);
  // the warm re-solve (solve_warm_shifted) after a move of 1e-3 r, on one and on two threads
  Problem q = p;
  q.spheres[0].center = q.spheres[0].center + Vec3{1e-3 * kR, 0, 0};
  std::vector<Solution> warm;
  const int saved = omp_get_max_threads();
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    auto solver = make_solver(o);
    solver->solve(p);
    warm.push_back(solver->solve(q));
  }
  omp_set_num_threads(saved);
  EXPECT_GT(warm[0].stats.iterations, 0);
  EXPECT_TRUE(warm[1].stats.extra.at("closed_from_kept_products").get<bool>()) << "the warm solve took a product more";
  expect_same_bits(warm[1], warm[0]);
}

// contact_low's GMRES closes without its explicit residual's product (solve_kept): alpha = M P^-1 u as the
// combination of the products it kept, beta = P^-1 u, the residual checked from them. Cold and warm solves at
// GMRES tolerance 1e-10 (kappa_p = 15, N = 30) against the unpreconditioned solve at 1e-12: forces and energy
// within 1e-8 (a wrong combination, e.g. one term short, misses by orders of magnitude more); the reported
// residual is the explicit one, <= 1e-10. Past kKeptProducts basis vectors (the cold solve at tolerance 1e-14:
// 25 iterations) the solve takes GMRES's own explicit residual instead and gives the same forces.
TEST(SpectralPreconditioner, ContactLowClosesFromKeptProducts) {
  const Problem p = random_cluster(30, 1.0, 15.0, 11);
  Problem q = p;
  q.spheres[3].center = q.spheres[3].center + Vec3{2e-3 * kR, 0, 0};
  SolverOptions ro = far_field_options("fmm");
  ro.tolerance = 1e-12;
  const Solution ref_p = make_solver(ro)->solve(p), ref_q = make_solver(ro)->solve(q);
  for (double tol : {1e-10, 1e-14}) {
    SolverOptions o = far_field_options("fmm");
    o.preconditioner = "contact_low";
    o.tolerance = tol;
    auto solver = make_solver(o);
    const Solution cold = solver->solve(p), warm = solver->solve(q);
    for (const auto& [name, s, ref] : {std::tuple{"cold", cold, ref_p}, std::tuple{"warm", warm, ref_q}}) {
      std::printf("contact_low, GMRES %.0e, %s: %d iterations, residual %.2e, kept %d, forces %.2e, energy %.2e\n",
                  tol, name, s.stats.iterations, s.stats.residual,
                  int(s.stats.extra.at("closed_from_kept_products").get<bool>()), force_difference(s, ref),
                  std::abs(s.energy - ref.energy) / std::abs(ref.energy));
      // the cold solve at 1e-14 takes 25 iterations (> kKeptProducts = 24), the others 13-20
      const bool past = tol < 1e-12 && std::string_view(name) == "cold";
      EXPECT_EQ(s.stats.extra.at("closed_from_kept_products").get<bool>(), !past) << name << " " << tol;
      EXPECT_EQ(s.stats.iterations > 24, past) << name << " " << tol;
      EXPECT_LE(s.stats.residual, tol) << name;
      EXPECT_LT(force_difference(s, ref), 1e-8) << name << " " << tol;
      EXPECT_LT(std::abs(s.energy - ref.energy), 1e-8 * std::abs(ref.energy)) << name << " " << tol;
    }
  }
}

// The near pairs of degree >= 20 rotate through the shared quarter turns (pivot_rotation.hpp); their twin
// rotates through stored blocks (FarFieldOptions::stored_rotations, the dense product's way). Cold fmm
// solves of the N = 50 cluster with near-contact gaps (L = 47; 36 of its 1184 near pairs take the quarter
// turns): forces and energy within 1e-10 of the twin (rounding only: measured 3.8e-16 and 0), the same
// GMRES iterations. (The same bits on 1 and 2 threads: SolutionDoesNotDependOnTheThreadCount.)
TEST(SpectralFarField, PivotRotationsMatchStoredRotations) {
  const Problem p = random_cluster(50, 1.0, 2.5, 11);
  const SolverOptions o = far_field_options("fmm");
  const sh::FarFieldOptions stored{.tolerance = far_field_tolerance(o), .stored_rotations = true};
  const Solution one = make_solver(o)->solve(p);
  const Solution twin = make_spectral_solver(o, stored)->solve(p);
  EXPECT_GT(one.stats.extra.at("pivot_pairs").get<int>(), 0) << "no pair took the quarter turns";
  EXPECT_EQ(twin.stats.extra.at("pivot_pairs").get<int>(), 0);
  const double force = force_difference(one, twin), energy = std::abs(one.energy - twin.energy) / std::abs(twin.energy);
  std::printf("pivot vs stored rotations: forces %.2e, energy %.2e, pivot pairs %d of %d\n", force, energy,
              one.stats.extra.at("pivot_pairs").get<int>(), one.stats.extra.at("near_pairs").get<int>());
  EXPECT_LE(force, 1e-10);
  EXPECT_LE(energy, 1e-10);
  EXPECT_EQ(one.stats.iterations, twin.stats.iterations);
}

// A D_f = 1.8 aggregate of the structure builder (the benchmark's, bench/bench_spectral_far_field.cpp):
// k_f = 1.3, r = 10 um, charges +-10 uC/m^2 alternating, kappa_p = 2.5, touching primaries 0.01 r apart.
Problem fractal_cluster(int n) {
  structure::FractalRequest q;
  q.primaries = n;
  q.fractal_dimension = 1.8;
  const structure::Aggregate a = structure::build_fractal(q);
  std::vector<double> charge(n), perm(n, 2.5);
  for (int i = 0; i < n; ++i) charge[i] = (i % 2 ? -1.0 : 1.0) * 10e-6 * 4 * constants::pi * a.r[i] * a.r[i];
  return make_problem(EsConfig{}, a.x, a.r, charge, perm);  // radii shrunk to gaps >= 0.01 r
}

// The cost model of --dry-run (spectral/cost.cpp) knows the fast far field: on the benchmark's D_f = 1.8
// aggregates from N = 250 to 1000 its steps and memory grow like the near pairs and M2L, about like N
// (measured x4.34 steps, x4.04 memory; asserted within 4^0.9 = 3.5 and 4^1.25 = 5.7). Counted over all
// pairs, as for the dense product, N = 1000 (499 500 pairs) is past the exact-pair limit and the estimate
// drops to its every-pair-at-degree-2 bound (x0.42 steps): the lower bound of the check fails then.
TEST(SpectralFarField, DryRunEstimateGrowsLikeN) {
  const Problem small = fractal_cluster(250), large = fractal_cluster(1000);
  const SolverOptions fast = far_field_options("fmm");
  const double steps = solver_steps(fast, large) / solver_steps(fast, small);
  const double bytes = solver_memory_bytes(fast, large) / solver_memory_bytes(fast, small);
  std::printf("fmm N 250 -> 1000: steps x%.2f, memory x%.2f; N = 1000: %.3g steps, %.3g bytes\n", steps, bytes,
              solver_steps(fast, large), solver_memory_bytes(fast, large));
  EXPECT_GE(steps, 3.5);
  EXPECT_LE(steps, 5.7);
  EXPECT_GE(bytes, 3.5);
  EXPECT_LE(bytes, 5.7);
}

// Negative controls: the tolerance check fails for a far field truncated two orders too low (p - 2 = 7:
// measured 2.7e-5 against 1e-5) or accepted too early (theta 0.9: 2.4e-3). One order too low (p - 1 = 8)
// gives 1.09e-5, above the tolerance by only 9 %: the order model is tight there, too tight for a control
// that must fail on every platform. (Random O(1) multipoles are no sharper control: the chosen p itself
// gives 1.7e-5 on them, since the model is fitted to solutions, whose high degrees are small.)
TEST(SpectralFarField, TooLowOrderOrTooLooseAcceptanceFailsTheTolerance) {
  const Problem p = random_cluster(200, 1.0, 2.5, 11);
  auto s = make_solver(far_field_options("fmm"));
  (void)s->solve(p);
  const auto beta = s->warm_start().values;
  const double tol = far_field_tolerance(far_field_options("fmm"));
  const int order = sh::far_field_order(tol);
  sh::FarFieldOptions low{.tolerance = tol, .order = order - 2};
  sh::FarFieldOptions loose{.theta = 0.9, .tolerance = tol, .order = order};
  const double e_low = product_error(p, beta, &low), e_loose = product_error(p, beta, &loose);
  std::printf("order %d: %.2e, theta 0.9: %.2e (tolerance %.0e)\n", order - 2, e_low, e_loose, tol);
  EXPECT_GT(e_low, tol);
  EXPECT_GT(e_loose, tol);
}

// The measurements behind the order model of far_field.hpp (0.1 x 0.35^p): product error against the
// dense twin for p = 2..12 on the four clusters (run with --gtest_also_run_disabled_tests).
TEST(SpectralFarField, DISABLED_ErrorVersusOrder) {
  for (double ratio : {1.0, 3.0})
    for (int n : {50, 200}) {
      const Problem p = random_cluster(n, ratio, 2.5, 11);
      auto dense = make_solver(far_field_options("dense"));
      (void)dense->solve(p);
      const auto beta = dense->warm_start().values;
      for (int order = 2; order <= 12; ++order) {
        const sh::FarFieldOptions fo{.order = order};
        std::printf("N = %d, radius ratio %g, p = %d: %.3e\n", n, ratio, order, product_error(p, beta, &fo));
      }
    }
}

// Right preconditioning (SolverOptions::preconditioner) keeps the true residual as GMRES's criterion, so
// a preconditioned solve is the same solution to within the GMRES tolerance (1e-6 here: forces within
// 1e-5 of the unpreconditioned twin). The contact network (every close pair's system at once) takes
// fewer iterations at kappa_p = 15, and so does its cheap form "contact_low"; block Jacobi over a
// matching of the close pairs, the negative control, does not (the chains of touching spheres are not in its blocks; docs/electrostatics.md).
TEST(SpectralPreconditioner, ContactNetworkGivesTheSameForcesInFewerIterations) {
  const Problem p = random_cluster(30, 1.0, 15.0, 11);
  SolverOptions ro = far_field_options("fmm");
  ro.tolerance = 1e-10;  // GMRES to 1e-10: the converged solution of the same discretisation
  const Solution ref = make_solver(ro)->solve(p);
  std::map<std::string, Solution> sol;
  for (std::string_view name : kPreconditionerNames) {
    SolverOptions o = far_field_options("fmm");
    o.preconditioner = std::string(name);
    const Solution& s = sol[o.preconditioner] = make_solver(o)->solve(p);
    std::printf("preconditioner %s: %d GMRES iterations, forces vs converged %.2e\n", o.preconditioner.c_str(),
                s.stats.iterations, force_difference(s, ref));
  }
  for (const auto& [name, s] : sol) EXPECT_LT(force_difference(s, ref), 1e-5) << name;
  const int none = sol["none"].stats.iterations;
  EXPECT_LE(sol["contact"].stats.iterations, none - 5);
  EXPECT_LE(sol["coarse"].stats.iterations, none);
  EXPECT_GT(sol["pair"].stats.iterations, none - 5);  // negative control: the matching is not enough
  // two Neumann steps of the contact system at degrees <= 20, frame orders <= 2 (the cheap one)
  EXPECT_LE(sol["contact_low"].stats.iterations, none - 3);
  EXPECT_GT(sol["contact"].stats.extra["preconditioner_inner_iterations"].get<long>(), 0);
}

// SolverOptions::contact_low_steps: its default kContactLowSteps (2; the same bits as 2 given explicitly); more
// steps take no more GMRES iterations on the kappa_p = 15 cluster and give the converged forces within 1e-5,
// and three steps give the same bits on one and two threads. Not vacuous: the steps change the iterate
// (1 and 3 steps give other bits than 2).
TEST(SpectralPreconditioner, ContactLowStepsOption) {
  const Problem p = random_cluster(30, 1.0, 15.0, 11);
  SolverOptions ro = far_field_options("fmm");
  ro.tolerance = 1e-10;
  const Solution ref = make_solver(ro)->solve(p);
  std::vector<Solution> sol;
  for (int steps : {0, 1, 2, 3}) {
    SolverOptions o = far_field_options("fmm");
    o.preconditioner = "contact_low";
    if (steps > 0) o.contact_low_steps = steps;  // 0: the default
    sol.push_back(make_solver(o)->solve(p));
    std::printf("contact_low, %d Neumann steps: %d GMRES iterations, forces vs converged %.2e\n", steps,
                sol.back().stats.iterations, force_difference(sol.back(), ref));
    EXPECT_LT(force_difference(sol.back(), ref), 1e-5) << steps << " steps";
  }
  expect_same_bits(sol[2], sol[0]);
  EXPECT_LE(sol[2].stats.iterations, sol[1].stats.iterations);
  EXPECT_LE(sol[3].stats.iterations, sol[2].stats.iterations);
  EXPECT_NE(sol[1].energy, sol[2].energy);
  EXPECT_NE(sol[3].energy, sol[2].energy);
  SolverOptions o3 = far_field_options("fmm");
  o3.preconditioner = "contact_low";
  o3.contact_low_steps = 3;
  const auto [one, two] = solve_on_one_and_two_threads(o3, random_cluster(300, 1.0, 15.0, 3));
  EXPECT_TRUE(two.stats.extra.at("contact_low_parallel").get<bool>());
  expect_same_bits(two, one);
}

// A warm start with a preconditioner starts GMRES from u = P x_prev (precondition_forward; contact_low:
// from the shifted system A P^-1 w = b - A x_prev, solve_warm_shifted): a moved cluster re-solved warm
// gives the cold solve's forces, in fewer iterations than cold.
TEST(SpectralPreconditioner, WarmStartMatchesColdSolve) {
  Problem p = random_cluster(20, 1.0, 15.0, 12);
  for (std::string_view name : {kPreconditionerNames[1], kPreconditionerNames[3], kPreconditionerNames[4]}) {
    SolverOptions o = far_field_options("fmm");
    o.preconditioner = std::string(name);
    auto warm = make_solver(o);
    warm->solve(p);
    Problem q = p;
    q.spheres[0].center = q.spheres[0].center + Vec3{1e-3 * kR, 0, 0};
    const Solution w = warm->solve(q);
    const Solution c = make_solver(o)->solve(q);
    EXPECT_LT(force_difference(w, c), 1e-5) << name;
    EXPECT_LT(w.stats.iterations, c.stats.iterations) << name;
  }
}

}  // namespace
}  // namespace agglo::es
