// Spectral solver, dense far field against the fast one (electrostatics.far_field, issue 25 item 1):
// one cold solve of a D_f = 1.8 aggregate of the structure builder (structure/fractal.hpp, k_f = 1.3,
// monodisperse r = 10 um, seed 1), charges +-10 uC/m^2 alternating, kappa_p = 2.5 and 15 (the
// products: 2.5 only), radii
// shrunk with g_min = 0.01 (touching primaries 0.01 r apart: L = 47 at the default target 1e-4).
// A solver is made anew for every solve (cold: no warm start). Reported per solve: process CPU time (both threads when OMP_NUM_THREADS=2), GMRES iterations and
// operator applications (matvecs), near pairs, M2L count, far-field order; the fmm run also reports
// the largest force difference against the dense run of the same N (force_vs_dense).
// "reference" (issue 25 item 3): the converged reference of the same aggregate, the fast far field at
// target accuracy kReferenceTarget (L = 71, pair degrees at 1e-3 of it, far-field order 14, GMRES to
// 1e-2 of it); every later solve of that N and kappa_p reports max_i |F_i - F_ref,i| / max_i |F_ref,i|
// (force_vs_reference), and "reference_check" (target kReferenceCheckTarget) the same against it: how far
// the reference itself is from converged. "bem": the seed paper's method on the same aggregate (BEM,
// FMM matvec, kBemPatches patches per sphere, GMRES to 1e-2 within 1000 iterations), against the reference as well.
// "fmm_pc_<name>": the fast far field with a right preconditioner (SolverOptions::preconditioner, the
// measuring tools of docs/electrostatics.md "Sixth session"); "fmm_acc<target>[_tol<GMRES tolerance>]
// [_L<fixed degree>]": the accuracy-cost rows at other settings, against the reference.
// bench/spectral_far_field.sh runs it and prints the per-solve and per-product ratios.
#include <benchmark/benchmark.h>

#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

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

// Target accuracies of the reference and of its check, patches per sphere of the BEM run.
constexpr double kReferenceTarget = 1e-6;
constexpr double kReferenceCheckTarget = 1e-7;
constexpr int kBemPatches = 100;

using Results = std::map<std::pair<int, double>, es::Solution>;
Results& dense_results() {
  static Results m;
  return m;
}
Results& reference_results() {
  static Results m;
  return m;
}

// far_field: "dense", "fmm", "fmm_stored" (fmm with the near pairs' stored rotation blocks,
// FarFieldOptions::stored_rotations, the twin of the shared quarter turns), "reference" and
// "reference_check" (fmm at kReferenceTarget, kReferenceCheckTarget), "bem" (header comment).
es::SolverOptions bench_options(const std::string& far_field) {
  es::SolverOptions o;
  o.far_field = far_field == "dense" ? "dense" : "fmm";
  if (far_field.starts_with("fmm_pc_")) o.preconditioner = far_field.substr(7);
  // "fmm_acc<target>[_tol<GMRES tolerance>][_L<fixed degree>][_pcl[<steps>]]": the accuracy-cost rows (_pcl:
  // with the contact_low preconditioner; _pcl3: with 3 Neumann steps)
  if (far_field.starts_with("fmm_acc")) {
    std::size_t at = 4;
    while (at < far_field.size()) {
      const std::size_t end = std::min(far_field.find('_', at), far_field.size());
      const std::string tok = far_field.substr(at, end - at);
      if (tok.starts_with("acc")) o.target_accuracy = std::stod(tok.substr(3));
      if (tok.starts_with("tol")) o.tolerance = std::stod(tok.substr(3));
      if (tok.starts_with("L")) o.max_degree = std::stoi(tok.substr(1));
      if (tok == "pcl") o.preconditioner = "contact_low";
      if (tok.starts_with("pcl") && tok.size() > 3) {  // pcl<steps>: contact_low with that many Neumann steps
        o.preconditioner = "contact_low";
        o.contact_low_steps = std::stoi(tok.substr(3));
      }
      at = end + 1;
    }
  }
  if (far_field == "reference") o.target_accuracy = kReferenceTarget;
  if (far_field == "reference_check") o.target_accuracy = kReferenceCheckTarget;
  if (far_field == "bem") {
    o.solver = "bem";
    o.patches_per_sphere = kBemPatches;
    o.tolerance = 1e-2;
    o.max_iterations = 1000;  // 200 (the default) were not enough at N = 1000 (relative residual 0.025)
    o.matvec = "fmm";
  }
  return o;
}
std::unique_ptr<es::Solver> bench_solver(const std::string& far_field) {
  const es::SolverOptions o = bench_options(far_field);
  if (far_field == "bem") return es::make_solver(o);
  es::sh::FarFieldOptions f{.tolerance = es::far_field_tolerance(o), .stored_rotations = far_field == "fmm_stored"};
  // "..._p<order>" (fmm_acc rows): the far field's expansion order fixed instead of taken from the target
  if (const std::size_t at = far_field.rfind("_p"); far_field.starts_with("fmm_acc") && at != std::string::npos &&
                                                    at + 2 < far_field.size() && std::isdigit(far_field[at + 2]))
    f.order = std::stoi(far_field.substr(at + 2));
  return es::make_spectral_solver(o, f);
}

// max_i |F_i - G_i| / max_i |G_i|
double force_difference(const es::Solution& f, const es::Solution& g) {
  double d = 0.0, r = 0.0;
  for (std::size_t i = 0; i < g.force.size(); ++i) {
    d = std::max(d, norm(f.force[i] - g.force[i]));
    r = std::max(r, norm(g.force[i]));
  }
  return d / r;
}

// "accept:<row>": the acceptance solve (1000 primaries, +-10 uC/m^2, force error <= 1e-4 against
// the converged reference, <= 1 s on 2 cores): <row> with the reference of the same N and kappa_p solved
// first (untimed) when this process has none, so that force_vs_reference is always reported.
constexpr std::string_view kAcceptPrefix = "accept:";

void solve(benchmark::State& st, const std::string& row, double kappa) {
  const int n = static_cast<int>(st.range(0));
  const es::Problem p = fractal_problem(n, kappa);
  const bool accept = row.starts_with(kAcceptPrefix);
  const std::string far_field = accept ? row.substr(kAcceptPrefix.size()) : row;
  // One untimed solve first: the process's heap then holds what a solve allocates (the first run of a
  // process otherwise pays the page faults of every later one). Not for the reference and the BEM
  // (each solve costs tens of seconds). The timed solver is destroyed after the timing: its release of
  // the memory (44 000 near pairs' blocks at N = 1000) is no part of the solve.
  const bool slow = far_field.starts_with("reference") || far_field == "bem";
  es::Solution sol;
  std::unique_ptr<es::Solver> timed;
  try {
    if (accept && !reference_results().contains({n, kappa}))
      reference_results()[{n, kappa}] = bench_solver("reference")->solve(p);
    if (!slow) sol = bench_solver(far_field)->solve(p);
    for (auto _ : st) {
      timed = bench_solver(far_field);
      sol = timed->solve(p);
    }
  } catch (const std::exception& e) {  // e.g. GMRES not converging: reported, the other runs go on
    st.SkipWithError(e.what());
    return;
  }
  st.counters["gmres_iterations"] = sol.stats.iterations;
  st.counters["degree"] = sol.stats.degree;
  if (sol.stats.extra.contains("near_pairs")) {
    st.counters["near_pairs"] = sol.stats.extra["near_pairs"].get<double>();
    st.counters["m2l"] = sol.stats.extra["m2l"].get<double>();
    st.counters["order"] = sol.stats.extra["far_field_order"].get<double>();
  }
  if (sol.stats.extra.contains("preconditioner_inner_iterations")) {
    st.counters["inner_iterations"] = sol.stats.extra["preconditioner_inner_iterations"].get<double>();
    st.counters["matched_pairs"] = sol.stats.extra["matched_pairs"].get<double>();
  }
  if (far_field == "dense") dense_results()[{n, kappa}] = sol;
  if (far_field == "reference") reference_results()[{n, kappa}] = sol;
  if (auto it = dense_results().find({n, kappa}); far_field != "dense" && it != dense_results().end())
    st.counters["force_vs_dense"] = force_difference(sol, it->second);
  if (auto it = reference_results().find({n, kappa}); far_field != "reference" && it != reference_results().end())
    st.counters["force_vs_reference"] = force_difference(sol, it->second);
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

// The references first: later solves of the same N and kappa_p compare with them. N = 10: the size of
// the smoke test (SMOKE=1 bench/spectral_far_field.sh, ctest -L bench).
BENCHMARK_CAPTURE(solve, reference_k2.5, std::string("reference"), 2.5)
    ->ArgName("N")->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, reference_k15, std::string("reference"), 15.0)
    ->ArgName("N")->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, reference_check_k2.5, std::string("reference_check"), 2.5)
    ->ArgName("N")->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(product, dense_k2.5, std::string("dense"), 2.5)
    ->ArgNames({"N", "products"})->ArgsProduct({{10, 100, 200, 400, 1000}, {1, 6}})
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(product, fmm_k2.5, std::string("fmm"), 2.5)
    ->ArgNames({"N", "products"})->ArgsProduct({{10, 100, 200, 400, 1000, 2000, 3000}, {1, 6}})
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(product, fmm_stored_k2.5, std::string("fmm_stored"), 2.5)
    ->ArgNames({"N", "products"})->ArgsProduct({{10, 100, 200, 400, 1000}, {1, 6}})
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, dense_k2.5, std::string("dense"), 2.5)
    ->ArgName("N")->Arg(10)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Arg(2000)->Arg(3000)
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, fmm_k2.5, std::string("fmm"), 2.5)
    ->ArgName("N")->Arg(10)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Arg(2000)->Arg(3000)
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, fmm_stored_k2.5, std::string("fmm_stored"), 2.5)
    ->ArgName("N")->Arg(10)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, dense_k15, std::string("dense"), 15.0)
    ->ArgName("N")->Arg(10)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, fmm_k15, std::string("fmm"), 15.0)
    ->ArgName("N")->Arg(10)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)
    ->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);

// Issue 25, sixth session: the right preconditioners (measuring tools, SolverOptions::preconditioner) and
// the accuracy-cost rows ("fmm_acc<target>[_tol<GMRES tolerance>][_L<fixed degree>]", bench_options),
// both kappa_p, after the references and the default solves that they are compared with.
const bool kSixthSessionRows = [] {
  const char* const preconditioners[] = {"fmm_pc_coarse", "fmm_pc_pair", "fmm_pc_contact", "fmm_pc_contact_low"};
  const char* const accuracies[] = {"fmm_acc1.5e-4",           "fmm_acc2e-4",          "fmm_acc2e-4_tol2e-6",
                                    "fmm_acc2e-4_L47",         "fmm_acc5e-4",          "fmm_acc5e-4_tol5e-6",
                                    "fmm_acc5e-4_L47",         "fmm_acc5e-4_tol5e-6_L47", "fmm_acc1e-3_tol1e-5",
                                    "fmm_acc1e-3_tol1e-5_L47", "fmm_acc1e-3_tol1e-5_pcl",
                                    "fmm_acc5e-4_tol5e-6_L47_pcl", "fmm_acc7e-4_tol7e-6_L47_pcl",
                                    "fmm_acc1e-3_tol1e-5_L49_pcl", "fmm_acc1e-3_tol1e-5_L51_pcl",
                                    "fmm_acc5e-4_tol5e-6_L43_pcl", "fmm_acc5e-4_tol5e-6_L43_pcl3"};
  auto add = [](const std::string& row, const std::vector<int>& ns) {
    for (const auto& [k, kappa] : {std::pair{"2.5", 2.5}, std::pair{"15", 15.0}}) {
      auto* b = benchmark::RegisterBenchmark(("solve/" + row + "_k" + k).c_str(),
                                             [row, kappa](benchmark::State& st) { solve(st, row, kappa); });
      b->ArgName("N")->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
      for (int n : ns) b->Arg(n);
    }
  };
  for (const char* row : preconditioners) add(row, {10, 100, 200, 1000});
  for (const char* row : accuracies) add(row, {10, 100, 1000});
  return true;
}();

// The acceptance solves of issue 25 (kAcceptPrefix): the cheapest settings measured with force error
// <= 1e-4 at N = 1000 (docs/electrostatics.md, "Seventh session" and "Eighth session"): kappa_p = 2.5
// target 1e-3, GMRES 1e-5, contact_low; kappa_p = 15 target 5e-4, GMRES 5e-6, L = 43, contact_low with three
// Neumann steps (force error 9.05e-5, 8 GMRES iterations; the seventh session's row, L = 47 and two steps,
// 5.09e-5 and 9: fmm_acc5e-4_tol5e-6_L47_pcl).
BENCHMARK_CAPTURE(solve, accept_k2.5, std::string(kAcceptPrefix) + "fmm_acc1e-3_tol1e-5_pcl", 2.5)
    ->ArgName("N")->Arg(1000)->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(solve, accept_k15, std::string(kAcceptPrefix) + "fmm_acc5e-4_tol5e-6_L43_pcl3", 15.0)
    ->ArgName("N")->Arg(1000)->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);

// More candidate settings for the acceptance solve, from the environment: AGGLO_ACCEPT_SCAN="<row>,<row>,..."
// (rows as "fmm_acc..." above) registers solve/scan_<row>_k<kappa> at N = 1000 for both kappa_p, each with its
// force error against the converged reference.
const bool kAcceptScanRows = [] {
  const char* env = std::getenv("AGGLO_ACCEPT_SCAN");
  std::string rows = env ? env : "";
  for (std::size_t at = 0; at < rows.size();) {
    const std::size_t end = std::min(rows.find(',', at), rows.size());
    const std::string row = rows.substr(at, end - at);
    at = end + 1;
    for (const auto& [k, kappa] : {std::pair{"2.5", 2.5}, std::pair{"15", 15.0}}) {
      auto* b = benchmark::RegisterBenchmark(("solve/scan_" + row + "_k" + k).c_str(), [row, kappa](benchmark::State& st) {
        solve(st, std::string(kAcceptPrefix) + row, kappa);
      });
      b->ArgName("N")->Arg(1000)->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);
    }
  }
  return true;
}();

// "machine/core_handoff": how long one core takes to hand a cache line to the other (two threads pass a
// token through one atomic, kHandoffs times each way; counter ns_per_handoff). On the project's two-vCPU
// machine it is bimodal: about 25-40 ns when the two vCPUs share a last-level cache and 160-180 ns when
// they do not, and the two-thread accept_k15 solve follows it (about 0.78 against 1.04 s): run it next
// to the acceptance rows to tell which machine a timing saw (docs/electrostatics.md, "Tenth session").
// Needs two free cores: on a busier machine a waiting thread may hold the core the other one needs.
constexpr long kHandoffs = 1000000;
void core_handoff(benchmark::State& st) {
  for (auto _ : st) {
    struct alignas(128) Token {  // a cache line of its own (no other data on it)
      std::atomic<long> v{0};
    };
    static Token token;
    token.v.store(0);
    auto pass = [](long first) {
      for (long i = first; i < 2 * kHandoffs; i += 2) {
        while (token.v.load(std::memory_order_acquire) != i) {
        }
        token.v.store(i + 1, std::memory_order_release);
      }
    };
    const auto t0 = std::chrono::steady_clock::now();
    std::thread other(pass, 1);
    pass(0);
    other.join();
    const std::chrono::duration<double, std::nano> dt = std::chrono::steady_clock::now() - t0;
    st.counters["ns_per_handoff"] = dt.count() / (2.0 * kHandoffs);
  }
}
BENCHMARK(core_handoff)->Name("machine/core_handoff")->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(solve, bem_k2.5, std::string("bem"), 2.5)
    ->ArgName("N")->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kSecond);

BENCHMARK_MAIN();
