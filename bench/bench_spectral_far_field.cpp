// Spectral solver, dense far field against the fast one (electrostatics.far_field, issue 25 item 1):
// one cold solve of a D_f = 1.8 aggregate of the structure builder (structure/fractal.hpp, k_f = 1.3,
// monodisperse r = 10 um, seed 1), charges +-10 uC/m^2 alternating, kappa_p = 2.5 and 15 (the
// products: 2.5 only), radii
// shrunk with g_min = 0.01 (touching primaries 0.01 r apart: L = 47 at the default target 1e-4).
// A solver is made anew for every solve (cold: no warm start). Reported per solve: process CPU time (both threads when OMP_NUM_THREADS=2), GMRES iterations and
// operator applications (matvecs), near pairs, M2L count, far-field order; the fmm run also reports
// the largest force difference against the dense run of the same N (force_vs_dense).
// bench/spectral_far_field.sh runs it and prints the per-solve and per-product ratios.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <string>

#include "agglo/core/constants.hpp"
#include "agglo/electrostatics/config.hpp"
#include "agglo/electrostatics/solver.hpp"
#include "agglo/electrostatics/spectral/spectral_solver.hpp"
#include "agglo/structure/fractal.hpp"

using namespace agglo;

namespace {

es::Problem fractal_problem(int n, double kappa) {
  structure::FractalRequest q;
  q.primaries = n;
  q.fractal_dimension = 1.8;
  const structure::Aggregate a = structure::build_fractal(q);
  std::vector<double> charge(n), perm(n, kappa);
  for (int i = 0; i < n; ++i) charge[i] = (i % 2 ? -1.0 : 1.0) * 10e-6 * 4 * constants::pi * a.r[i] * a.r[i];
  return es::make_problem(es::EsConfig{}, a.x, a.r, charge, perm);
}

std::map<std::pair<int, double>, es::Solution>& dense_results() {
  static std::map<std::pair<int, double>, es::Solution> m;
  return m;
}

// far_field "fmm_stored": fmm with the near pairs' stored rotation blocks (FarFieldOptions::stored_rotations,
// the twin of the shared quarter turns).
es::SolverOptions bench_options(const std::string& far_field) {
  es::SolverOptions o;
  o.far_field = far_field == "dense" ? "dense" : "fmm";
  return o;
}
std::unique_ptr<es::Solver> bench_solver(const std::string& far_field) {
  const es::SolverOptions o = bench_options(far_field);
  es::sh::FarFieldOptions f{.tolerance = es::far_field_tolerance(o), .stored_rotations = far_field == "fmm_stored"};
  return es::make_spectral_solver(o, f);
}

void solve(benchmark::State& st, const std::string& far_field, double kappa) {
  const int n = static_cast<int>(st.range(0));
  const es::Problem p = fractal_problem(n, kappa);
  // One untimed solve first: the process's heap then holds what a solve allocates (the first run of a
  // process otherwise pays the page faults of every later one).
  es::Solution sol = bench_solver(far_field)->solve(p);
  for (auto _ : st) sol = bench_solver(far_field)->solve(p);
  st.counters["gmres_iterations"] = sol.stats.iterations;
  st.counters["degree"] = sol.stats.degree;
  if (sol.stats.extra.contains("near_pairs")) {
    st.counters["near_pairs"] = sol.stats.extra["near_pairs"].get<double>();
    st.counters["m2l"] = sol.stats.extra["m2l"].get<double>();
    st.counters["order"] = sol.stats.extra["far_field_order"].get<double>();
  }
  auto& dense = dense_results();
  if (far_field == "dense") {
    dense[{n, kappa}] = sol;
  } else if (auto it = dense.find({n, kappa}); it != dense.end()) {
    double d = 0.0, r = 0.0;
    for (int i = 0; i < n; ++i) {
      d = std::max(d, norm(sol.force[i] - it->second.force[i]));
      r = std::max(r, norm(it->second.force[i]));
    }
    st.counters["force_vs_dense"] = d / r;
  }
}

// Set-up (degree, pairs, tree) and `repeat` products alpha = M beta (beta = 1 everywhere): the runs
// with 1 and 6 products give the cost of one product (spectral_far_field.sh).
void product(benchmark::State& st, const std::string& far_field, double kappa) {
  const int repeat = static_cast<int>(st.range(1));
  const es::Problem p = fractal_problem(static_cast<int>(st.range(0)), kappa);
  const es::SolverOptions o = bench_options(far_field);
  const es::sh::FarFieldOptions f{.tolerance = es::far_field_tolerance(o), .stored_rotations = far_field == "fmm_stored"};
  const int L = es::spectral_degree(o, p);
  const std::vector<double> beta(p.spheres.size() * std::size_t(L + 1) * (L + 1), 1.0);
  benchmark::DoNotOptimize(es::spectral_product(o, p, beta, &f));  // untimed, as in solve()
  for (auto _ : st) benchmark::DoNotOptimize(es::spectral_product(o, p, beta, &f, repeat));
}

}  // namespace

BENCHMARK_CAPTURE(product, dense_k2.5, std::string("dense"), 2.5)
    ->ArgNames({"N", "products"})->ArgsProduct({{100, 200, 400, 1000}, {1, 6}})
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(product, fmm_k2.5, std::string("fmm"), 2.5)
    ->ArgNames({"N", "products"})->ArgsProduct({{100, 200, 400, 1000, 2000, 3000}, {1, 6}})
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(product, fmm_stored_k2.5, std::string("fmm_stored"), 2.5)
    ->ArgNames({"N", "products"})->ArgsProduct({{100, 200, 400, 1000}, {1, 6}})
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, dense_k2.5, std::string("dense"), 2.5)
    ->ArgName("N")->Arg(100)->Arg(200)->Arg(400)->Arg(1000)
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, fmm_k2.5, std::string("fmm"), 2.5)
    ->ArgName("N")->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Arg(2000)->Arg(3000)
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, fmm_stored_k2.5, std::string("fmm_stored"), 2.5)
    ->ArgName("N")->Arg(100)->Arg(200)->Arg(400)->Arg(1000)
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, dense_k15, std::string("dense"), 15.0)
    ->ArgName("N")->Arg(100)->Arg(200)->Arg(400)->Arg(1000)
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, fmm_k15, std::string("fmm"), 15.0)
    ->ArgName("N")->Arg(100)->Arg(200)->Arg(400)->Arg(1000)
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);

BENCHMARK_MAIN();
