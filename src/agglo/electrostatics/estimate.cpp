#include "agglo/electrostatics/estimate.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/settings_electrostatics.hpp"
#include "agglo/electrostatics/sphere_mesh.hpp"
#include "agglo/electrostatics/spectral/degree.hpp"

namespace agglo::es {

namespace {

// Above this many sphere pairs the spectral estimate stops computing each pair's degree.
constexpr double kExactPairLimit = 2e5;
// A spectral pair record without its rotation data: indices, ratios and the rotation's vector headers.
constexpr double kSpectralPairBytes = 320.0;
// BEM arrays per patch besides the GMRES basis: patch set (92 B), operator buffers (88 B), solver
// vectors (about 100 B), FMM points, expansions and lists (about 150 B), surface samples twice
// (the solver's and the writer's copy, 2 x 80 B).
constexpr double kBemArrayBytesPerPatch = 600.0;
// Per sphere: the Problem, the Solution and the writer's rows.
constexpr double kSphereBytes = 256.0;
// Bytes of one surface.vtu sample in the binary file (point and normal 2 x 24, area and three
// densities 32, body 4, its two triangles 2 x 17 with Int32 indices: 118 B) and of one
// forces.csv row; the small JSON files.
constexpr double kVtuSampleBytes = 118.0;
// Held per sample while surface.vtu is written: the writer's double arrays (11 per point, 10 per
// two cells) and the encoded bytes of one array (at most a 3-vector, 24 B).
constexpr double kVtuWriteBytes = 21.0 * 8.0 + 24.0;
constexpr double kForcesRowBytes = 180.0;
constexpr double kSmallFilesBytes = 64.0 * 1024.0;

// Doubles of a FrameRotation of degree L with every frame order (spectral/rotation.cpp): Wigner d,
// real blocks, cos/sin, factorial and square-root tables.
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

// The global degree of the spectral solver (SpectralSolver::choose_degree).
int spectral_degree(const SolverOptions& opt, const Problem& p) {
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

// Calls f(L_pair) for every sphere pair, as SpectralSolver::build_pairs chooses the pair degrees;
// every pair at degree 2 above kExactPairLimit pairs. Returns the global degree.
template <class F>
int for_pair_degrees(const SolverOptions& opt, const Problem& p, F&& f) {
  const double n = static_cast<double>(p.spheres.size()), pairs = 0.5 * n * (n - 1.0);
  if (pairs > kExactPairLimit) {
    f(2, pairs);
    return 2;
  }
  const int L = spectral_degree(opt, p);
  for (std::size_t i = 0; i < p.spheres.size(); ++i)
    for (std::size_t k = i + 1; k < p.spheres.size(); ++k) {
      const auto &a = p.spheres[i], &b = p.spheres[k];
      const auto r = sh::limit_ratios(a.radius, b.radius, norm(b.center - a.center));
      f(std::min(L, std::max(2, sh::degree_for(r, 1e-3 * opt.target_accuracy))), 1.0);
    }
  return L;
}

double bem_patch_bytes(const SolverOptions& opt) {
  return 8.0 * (std::min(opt.max_iterations, 100) + 1.0) + kBemArrayBytesPerPatch;
}

double spectral_bytes(const SolverOptions& opt, const Problem& p) {
  double bytes = 0.0;
  const int L = for_pair_degrees(opt, p, [&](int Lp, double count) {
    bytes += count * (kSpectralPairBytes + 8.0 * rotation_doubles(Lp));
  });
  const double n = static_cast<double>(p.spheres.size()), nc = (L + 1.0) * (L + 1.0);
  return bytes + 8.0 * n * nc * (10.0 + std::min(opt.max_iterations, 100) + 1.0);
}

}  // namespace

double solver_memory_bytes(const SolverOptions& opt, const Problem& p) {
  const double n = static_cast<double>(p.spheres.size());
  if (opt.solver == "spectral") return spectral_bytes(opt, p) + kSphereBytes * n;
  if (opt.solver == "bem") return n * opt.patches_per_sphere * bem_patch_bytes(opt) + kSphereBytes * n;
  return kSphereBytes * n;
}

double solver_steps(const SolverOptions& opt, const Problem& p) {
  const double n = static_cast<double>(p.spheres.size());
  if (opt.solver == "spectral") {
    double work = 0.0;
    for_pair_degrees(opt, p, [&](int Lp, double count) { work += count * std::pow(Lp + 1.0, 3.0); });
    return opt.max_iterations * work + n * n;
  }
  if (opt.solver == "bem") {
    const double patches = n * opt.patches_per_sphere;
    return opt.max_iterations * patches * (opt.matvec == "direct" ? patches : 27.0 * opt.fmm_leaf_size);
  }
  return n * n;
}


double surface_samples(const SolverOptions& opt, double spheres) {
  if (opt.solver == "bem") return spheres * opt.patches_per_sphere;
  const int level = icosphere_level_for(opt.solver == "coulomb" ? std::min(opt.patches_per_sphere, 642)
                                                                : opt.patches_per_sphere);
  return spheres * (10.0 * std::pow(4.0, level) + 2.0);
}

namespace {
Estimate assemble(const SolverOptions& opt, double n, double steps, double solver_bytes, bool surface) {
  const auto& k = settings::electrostatics_settings();
  const std::string particles = "[[" + std::string(k.particles.t.name()) + "]]";
  const std::string solver(k.solver.solver.dotted()), patches(k.solver.patches_per_sphere.dotted());
  const double samples = surface ? surface_samples(opt, n) : 0.0;
  std::vector<std::string> keys{particles, solver};
  if (opt.solver == "bem") keys.insert(keys.begin(), patches);
  if (opt.solver == "spectral") keys.emplace_back(k.solver.max_degree_limit.dotted());
  Estimate e;
  add_to(e.steps, steps, keys);
  add_to(e.steps, 0.0, {std::string(k.solver.max_iterations.dotted())});
  add_to(e.output, samples * kVtuSampleBytes + n * kForcesRowBytes + kSmallFilesBytes, {particles, patches});
  // The surface samples (80 B each, two copies) and the writer's arrays and bytes of surface.vtu.
  add_to(e.memory, solver_bytes + samples * (160.0 + kVtuWriteBytes), keys);
  return e;
}
}  // namespace

Estimate static_solve_estimate(const SolverOptions& opt, const Problem& p, bool surface) {
  return assemble(opt, static_cast<double>(p.spheres.size()), solver_steps(opt, p), solver_memory_bytes(opt, p),
                  surface);
}

Estimate static_solve_lower_bound(const SolverOptions& opt, double spheres, bool surface) {
  const double pairs = 0.5 * spheres * (spheres - 1.0);
  double bytes = kSphereBytes * spheres;
  if (opt.solver == "spectral") bytes += pairs * (kSpectralPairBytes + 8.0 * rotation_doubles(2.0));
  if (opt.solver == "bem") bytes += spheres * opt.patches_per_sphere * bem_patch_bytes(opt);
  return assemble(opt, spheres, spheres * spheres, bytes, surface);
}

}  // namespace agglo::es
