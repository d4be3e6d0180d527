// The spectral solver's type and cost model (registry.hpp, estimate.hpp): one pair record per sphere
// pair, N (N - 1) / 2, each with the Wigner rotation of its degree L_pair (about L_pair^3 doubles;
// L_pair chosen as the solver does, degree.hpp), plus O(N (L+1)^2) coefficient vectors and the GMRES
// basis; work max_iterations x sum over pairs of (L_pair + 1)^3 (one rotation-based translation).
// The degree needs every pair: above kExactPairLimit pairs the estimate uses L_pair = 2 (a lower
// bound, still enough to refuse a case of 1e5 spheres).
// far_field = "fmm" (far_field.hpp): the pairs are the near pairs of the octree (built here as the
// solver builds it, O(N log N)), the global degree is their largest (the far pairs are well separated),
// near pairs of degree >= kPivotDegree hold O(L) numbers (pivot_rotation.hpp), and each product adds
// the far field, (M2L count + 2 (N + cells)) (p + 1)^4 / 4 units: at N = 1000 (D_f = 1.8, p = 9) the far
// field took about a fifth of the near pairs' time in a profile of the solve (perf, 6 % against 28 %),
// and its M2L count x (p + 1)^4 is about the near pairs' sum of (L_pair + 1)^3. The estimate then grows
// like the near pairs, O(N) (tests/electrostatics/test_spectral_far_field.cpp).
#include <algorithm>
#include <cmath>

#include <omp.h>

#include "agglo/electrostatics/sphere_mesh.hpp"
#include "agglo/electrostatics/spectral/degree.hpp"
#include "agglo/electrostatics/spectral/far_field.hpp"
#include "agglo/electrostatics/spectral/spectral_solver.hpp"

namespace agglo::es {

namespace {

// Above this many sphere pairs the estimate stops computing each pair's degree.
constexpr double kExactPairLimit = 2e5;
// A pair record without its rotation data: indices, ratios and the rotation's vector headers.
constexpr double kPairBytes = 320.0;
// One thread, against the bound with every GMRES iteration allowed: 6e-10 s per pair coefficient
// (the shipped tetrahedron 0.10 s for 1.77e8; the 30-sphere cluster of tests/cli/interrupt_phases.sh
// 0.51 s for 2.32e9).
constexpr double kSecondsPerInteraction = 6e-10;

// Doubles of a FrameRotation of degree L with every frame order (rotation.cpp): Wigner d, real
// blocks, cos/sin, factorial and square-root tables.
double rotation_doubles(double L) {
  double d = 0.0, blk = 0.0;
  for (int l = 0; l <= static_cast<int>(L); ++l) {
    d += (l + 1.0) * (l + 1.0);
    blk += (l + 1.0) * (l + 1.0) + static_cast<double>(l) * l;
  }
  return d + blk + 2.0 * (L + 2.0) * (L + 2.0) + 6.0 * (L + 2.0);
}

bool polarisable_pair(const Problem& p, const Sphere& a, const Sphere& b) {
  return a.permittivity != p.medium_permittivity || b.permittivity != p.medium_permittivity;
}

// The global degree of the solver (SpectralSolver::choose_degree).
int global_degree(const SolverOptions& opt, const Problem& p) {
  if (opt.max_degree > 0) return opt.max_degree;
  int L = 2;
  const std::size_t n = p.spheres.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = i + 1; k < n; ++k) {
      const auto &a = p.spheres[i], &b = p.spheres[k];
      if (!polarisable_pair(p, a, b)) continue;
      L = std::max(L, sh::degree_for(sh::limit_ratios(a.radius, b.radius, norm(b.center - a.center)),
                                     opt.target_accuracy));
    }
  return std::min(L, opt.max_degree_limit);
}

bool fast_far_field(const SolverOptions& opt) { return opt.far_field == kFarFieldNames[1]; }

// far_field = "fmm": the octree's near pairs (the solver's far-field options) with their degrees at
// target t, and the far field's units of work per product (see the header comment).
struct NearPairs {
  std::vector<std::array<int, 2>> pairs;
  int L = 2;
  double far_work = 0.0;
};
NearPairs near_pairs(const SolverOptions& opt, const Problem& p) {
  sh::FarFieldOptions fo;
  fo.tolerance = far_field_tolerance(opt);
  const sh::SphereFarField ff(p, 2, fo);  // the classification does not depend on the degree
  NearPairs r{ff.near_pairs(), 2, 0.0};
  const double q = ff.order() + 1.0;
  r.far_work = (static_cast<double>(ff.m2l_count()) + 2.0 * (static_cast<double>(p.spheres.size()) + ff.cells())) *
               q * q * q * q / 4.0;
  if (opt.max_degree > 0) {
    r.L = opt.max_degree;
    return r;
  }
  for (const auto& [i, k] : r.pairs) {
    const auto &a = p.spheres[i], &b = p.spheres[k];
    if (!polarisable_pair(p, a, b)) continue;
    r.L = std::max(r.L, sh::degree_for(sh::limit_ratios(a.radius, b.radius, norm(b.center - a.center)),
                                       opt.target_accuracy));
  }
  r.L = std::min(r.L, opt.max_degree_limit);
  return r;
}

// Calls f(L_pair, count) for every sphere pair (far_field = "fmm": every near pair), as
// SpectralSolver::build_pairs chooses the pair degrees; every pair at degree 2 above kExactPairLimit
// pairs. Returns the global degree; far_work (if given) gets the far field's work per product.
template <class F>
int for_pair_degrees(const SolverOptions& opt, const Problem& p, F&& f, double* far_work = nullptr) {
  if (fast_far_field(opt)) {
    const NearPairs np = near_pairs(opt, p);
    if (far_work) *far_work = np.far_work;
    if (static_cast<double>(np.pairs.size()) > kExactPairLimit) {
      f(2, static_cast<double>(np.pairs.size()));
      return 2;
    }
    for (const auto& [i, k] : np.pairs) {
      const auto &a = p.spheres[i], &b = p.spheres[k];
      const auto r = sh::limit_ratios(a.radius, b.radius, norm(b.center - a.center));
      f(std::min(np.L, std::max(2, sh::degree_for(r, 1e-3 * opt.target_accuracy))), 1.0);
    }
    return np.L;
  }
  const double n = static_cast<double>(p.spheres.size()), pairs = 0.5 * n * (n - 1.0);
  if (pairs > kExactPairLimit) {
    f(2, pairs);
    return 2;
  }
  const int L = global_degree(opt, p);
  for (std::size_t i = 0; i < p.spheres.size(); ++i)
    for (std::size_t k = i + 1; k < p.spheres.size(); ++k) {
      const auto &a = p.spheres[i], &b = p.spheres[k];
      const auto r = sh::limit_ratios(a.radius, b.radius, norm(b.center - a.center));
      f(std::min(L, std::max(2, sh::degree_for(r, 1e-3 * opt.target_accuracy))), 1.0);
    }
  return L;
}

double spectral_memory_bytes(const SolverOptions& opt, const Problem& p) {
  double bytes = 0.0;
  const bool pivots = fast_far_field(opt);  // pairs of degree >= kPivotDegree: cos/sin of two angles
  const int L = for_pair_degrees(opt, p, [&](int Lp, double count) {
    bytes += count * (kPairBytes + 8.0 * (pivots && Lp >= kPivotDegree ? 4.0 * (Lp + 1.0) : rotation_doubles(Lp)));
  });
  const double n = static_cast<double>(p.spheres.size()), nc = (L + 1.0) * (L + 1.0);
  // per sphere: solution, GMRES basis; per pair of a block of products (at most 128) and per thread
  const double block = std::min(0.5 * n * (n - 1.0), 128.0), threads = omp_get_max_threads();
  return bytes + 8.0 * nc * (n * (10.0 + std::min(opt.max_iterations, 100) + 1.0) + 2.0 * block + 4.0 * threads);
}

double spectral_memory_lower_bound(const SolverOptions& opt, double spheres) {
  // fmm: the near pairs are not known without the tree; the solution and ten GMRES vectors at degree 2
  if (fast_far_field(opt)) return spheres * 11.0 * 9.0 * 8.0;
  return 0.5 * spheres * (spheres - 1.0) * (kPairBytes + 8.0 * rotation_doubles(2.0));
}

double spectral_interactions(const SolverOptions& opt, const Problem& p) {
  double work = 0.0, far = 0.0;
  for_pair_degrees(opt, p, [&](int Lp, double count) { work += count * std::pow(Lp + 1.0, 3.0); }, &far);
  const double n = static_cast<double>(p.spheres.size());
  return opt.max_iterations * (work + far) + n * n;
}

double samples_per_sphere(const SolverOptions& opt) {
  return static_cast<double>(icosphere_vertices_for(opt.patches_per_sphere));
}

}  // namespace

SolverType spectral_solver_type() {
  return {.name = kSpectralSolver,
          .make = &make_spectral_solver,
          .memory_bytes = &spectral_memory_bytes,
          .memory_lower_bound = &spectral_memory_lower_bound,
          .interactions = &spectral_interactions,
          .samples_per_sphere = &samples_per_sphere,
          .seconds_per_interaction = [](const SolverOptions&) { return kSecondsPerInteraction; },
          .cost_keys = {"max_degree_limit"}};
}

}  // namespace agglo::es
