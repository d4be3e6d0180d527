#include "agglo/electrostatics/estimate.hpp"

#include "agglo/core/settings_electrostatics.hpp"
#include "agglo/electrostatics/keys.hpp"
#include "agglo/electrostatics/registry.hpp"

namespace agglo::es {

namespace {

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

double point_interactions(double spheres) { return spheres * spheres; }

}  // namespace

double solver_memory_bytes(const SolverOptions& opt, const Problem& p) {
  const SolverType& t = solver_type(opt.solver);
  const double n = static_cast<double>(p.spheres.size());
  return kSphereBytes * n + (t.memory_bytes ? t.memory_bytes(opt, p) : 0.0);
}

double solver_steps(const SolverOptions& opt, const Problem& p) {
  const SolverType& t = solver_type(opt.solver);
  return t.interactions ? t.interactions(opt, p) : point_interactions(static_cast<double>(p.spheres.size()));
}

double surface_samples(const SolverOptions& opt, double spheres) {
  const SolverType& t = solver_type(opt.solver);
  return spheres * (t.samples_per_sphere ? t.samples_per_sphere(opt) : 1.0);
}

double seconds_per_interaction(const SolverOptions& opt) {
  const SolverType& t = solver_type(opt.solver);
  return t.seconds_per_interaction ? t.seconds_per_interaction(opt) : kPointChargeSeconds;
}

bool induces_charges(const SolverOptions& opt) { return solver_type(opt.solver).induced_charges; }

namespace {
// The keys that drive the cost: the solver's own (most important first), the sphere list, the solver.
std::vector<std::string> cost_keys(const SolverOptions& opt, const std::string& particles) {
  std::vector<std::string> keys;
  for (std::string_view leaf : solver_type(opt.solver).cost_keys)
    keys.push_back(std::string(solver_keys().t.name()) + "." + std::string(leaf));
  keys.push_back(particles);
  keys.emplace_back(solver_keys().solver.dotted());
  return keys;
}

Estimate assemble(const SolverOptions& opt, double n, double steps, double solver_bytes, bool surface) {
  const auto& k = settings::electrostatics_settings();
  const std::string particles = "[[" + std::string(k.particles.t.name()) + "]]";
  const double samples = surface ? surface_samples(opt, n) : 0.0;
  const std::vector<std::string> keys = cost_keys(opt, particles);
  Estimate e;
  add_to(e.steps, steps, keys);
  add_to(e.steps, 0.0, {std::string(solver_keys().max_iterations.dotted())});
  add_to(e.output, samples * kVtuSampleBytes + n * kForcesRowBytes + kSmallFilesBytes,
         {particles, std::string(solver_keys().patches_per_sphere.dotted())});
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
  const SolverType& t = solver_type(opt.solver);
  const double bytes = kSphereBytes * spheres + (t.memory_lower_bound ? t.memory_lower_bound(opt, spheres) : 0.0);
  return assemble(opt, spheres, point_interactions(spheres), bytes, surface);
}

}  // namespace agglo::es
