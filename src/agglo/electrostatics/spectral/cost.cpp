// The spectral solver's type and cost model (registry.hpp, estimate.hpp): one pair record per sphere
// pair, N (N - 1) / 2, each with the Wigner rotation of its degree L_pair (about L_pair^3 doubles;
// L_pair chosen as the solver does, degree.hpp), plus O(N (L+1)^2) coefficient vectors and the GMRES
// basis; work max_iterations x sum over pairs of (L_pair + 1)^3 (one rotation-based translation).
// The degree needs every pair: above kExactPairLimit pairs the estimate uses L_pair = 2 (a lower
// bound, still enough to refuse a case of 1e5 spheres).
#include <algorithm>
#include <cmath>

#include <omp.h>

#include "agglo/electrostatics/sphere_mesh.hpp"
#include "agglo/electrostatics/spectral/degree.hpp"
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

// Calls f(L_pair, count) for every sphere pair, as SpectralSolver::build_pairs chooses the pair
// degrees; every pair at degree 2 above kExactPairLimit pairs. Returns the global degree.
template <class F>
int for_pair_degrees(const SolverOptions& opt, const Problem& p, F&& f) {
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
  const int L = for_pair_degrees(opt, p, [&](int Lp, double count) {
    bytes += count * (kPairBytes + 8.0 * rotation_doubles(Lp));
  });
  const double n = static_cast<double>(p.spheres.size()), nc = (L + 1.0) * (L + 1.0);
  // per sphere: solution, GMRES basis; per pair of a block of products (at most 128) and per thread
  const double block = std::min(0.5 * n * (n - 1.0), 128.0), threads = omp_get_max_threads();
  return bytes + 8.0 * nc * (n * (10.0 + std::min(opt.max_iterations, 100) + 1.0) + 2.0 * block + 4.0 * threads);
}

double spectral_memory_lower_bound(const SolverOptions&, double spheres) {
  return 0.5 * spheres * (spheres - 1.0) * (kPairBytes + 8.0 * rotation_doubles(2.0));
}

double spectral_interactions(const SolverOptions& opt, const Problem& p) {
  double work = 0.0;
  for_pair_degrees(opt, p, [&](int Lp, double count) { work += count * std::pow(Lp + 1.0, 3.0); });
  const double n = static_cast<double>(p.spheres.size());
  return opt.max_iterations * work + n * n;
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
