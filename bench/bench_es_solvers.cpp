// One electrostatic solve of the seed's 5-sphere configuration near contact (docs/model.md §A.3/§B.3):
// 4 spheres r = 10 um in a regular tetrahedron at the JKR equilibrium overlap, charges
// +-10 uC/m^2 * 4 pi r^2 alternating, kappa_p = 15, plus a neutral kappa 15 projectile touching
// one edge; radii shrunk with g_min = 0.01 (electrostatic gaps ~0.01 r). Each solver's force
// error against a converged spectral reference (L = 80, target 1e-10, GMRES 1e-11;
// L = 80 and L = 100 differ by 6e-8) is reported as a counter:
// err = max_i |F_i - F_ref,i| / max_i |F_ref,i|.
// "cold": a new solver per solve; "warm": one solver, the projectile moves 0.1 nm per solve
// (the DEM situation: warm start from the previous solution).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "agglo/core/constants.hpp"
#include "agglo/electrostatics/config.hpp"
#include "agglo/electrostatics/solver.hpp"

using namespace agglo;
using namespace agglo::es;

namespace {

Problem seed_configuration() {
  const double r = 10e-6, pi = constants::pi;
  // JKR equilibrium overlap (docs/model.md §A.3 defaults): delta0 = a0^2 / (3 R*)
  const double E = 1e9, nu = 0.33, gamma = 0.01, Rs = r / 2;
  const double Es = E / (2 * (1 - nu * nu));
  const double a0 = std::cbrt(9 * pi * gamma * Rs * Rs / Es);
  const double d0 = a0 * a0 / (3 * Rs);
  const double s = 2 * r - d0;
  const Vec3 v[4] = {{0, 0, 0}, {s, 0, 0}, {s / 2, s * std::sqrt(3.0) / 2, 0},
                     {s / 2, s * std::sqrt(3.0) / 6, s * std::sqrt(2.0 / 3.0)}};
  const double q = 10e-6 * 4 * pi * r * r;
  const double sg[4] = {1, -1, 1, -1};
  std::vector<Vec3> c(v, v + 4);
  c.push_back(Vec3{s / 2, -std::sqrt(s * s - s * s / 4), 0});  // projectile touching spheres 0 and 1
  EsConfig ec;  // g_min = 0.01
  return make_problem(ec, c, std::vector<double>(5, r), {sg[0] * q, sg[1] * q, sg[2] * q, sg[3] * q, 0.0},
                      std::vector<double>(5, 15.0));
}

const Solution& reference() {
  static Solution ref = [] {
    SolverOptions o;
    o.max_degree = 80;
    o.target_accuracy = 1e-10;  // also sets the pair truncations (1e-2 x target)
    o.tolerance = 1e-11;
    o.max_iterations = 1000;
    return make_solver(o)->solve(seed_configuration());
  }();
  return ref;
}

double force_error(const Solution& s) {
  const auto& ref = reference();
  double num = 0, den = 0;
  for (std::size_t i = 0; i < s.force.size(); ++i) {
    num = std::max(num, norm(s.force[i] - ref.force[i]));
    den = std::max(den, norm(ref.force[i]));
  }
  return num / den;
}

SolverOptions options(const std::string& name, double target) {
  SolverOptions o;
  o.solver = name;
  o.target_accuracy = target;
  return o;
}

void run(benchmark::State& state, const std::string& name, double target, bool warm) {
  Problem p = seed_configuration();
  reference();
  std::unique_ptr<Solver> solver;
  try {
    solver = make_solver(options(name, target));
    solver->solve(p);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  Solution sol = solver->solve(p);
  const double err = force_error(sol);
  int it = 0;
  for (auto _ : state) {
    if (!warm) {
      state.PauseTiming();
      solver = make_solver(options(name, target));
      state.ResumeTiming();
      sol = solver->solve(p);
    } else {
      p.spheres[4].center.y -= 1e-10;  // 0.1 nm per solve
      sol = solver->solve(p);
    }
    it = sol.stats.iterations;
    benchmark::DoNotOptimize(sol.energy);
  }
  state.counters["force_err"] = err;
  state.counters["degree"] = sol.stats.degree;
  state.counters["iterations"] = it;
}

}  // namespace

BENCHMARK_CAPTURE(run, coulomb, std::string("coulomb"), 1e-4, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, spectral_1e3_cold, std::string("spectral"), 1e-3, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, spectral_1e3_warm, std::string("spectral"), 1e-3, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, spectral_1e4_cold, std::string("spectral"), 1e-4, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, spectral_1e4_warm, std::string("spectral"), 1e-4, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, spectral_1e6_cold, std::string("spectral"), 1e-6, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, bem_cold, std::string("bem"), 1e-4, false)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
