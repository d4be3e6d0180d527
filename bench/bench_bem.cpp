// One BEM solve of the seed's 5-sphere configuration (docs/model.md §A.3 / seed 000): a tetrahedron of
// four touching r = 10 um spheres with alternating charges +-10 uC/m^2 * 4 pi r^2 and a projectile
// sphere touching the top one, kappa_p = 15, electrostatic radius r/(1 + g_min/2), g_min = 0.01
// (docs/model.md §B.3). 2000 patches per sphere, direct and FMM matvec; cold start and warm start after
// moving the projectile by 1 % of the gap. Counters: iterations, matvecs, FMM order, force on the
// projectile, and its relative difference from the direct solve at the same position.
// Also: accuracy against the docs/model.md §B.4 table vs patch count (BM_BemTwoSphereAccuracy). Run:
//   OMP_NUM_THREADS=2 ./bench_bem --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "agglo/core/constants.hpp"
#include "agglo/electrostatics/bem/bem_solver.hpp"

using namespace agglo;
using namespace agglo::es;

namespace {

Problem five_spheres(double shift) {
  const double r = 10e-6, rE = r / (1.0 + 0.01 / 2), sigma = 10e-6, q = sigma * 4 * constants::pi * r * r;
  // Regular tetrahedron with edge 2r (touching spheres), base in the z = 0 plane.
  const double a = 2 * r;
  const Vec3 v0{0, 0, 0}, v1{a, 0, 0}, v2{a / 2, a * std::sqrt(3.0) / 2, 0};
  const Vec3 top{a / 2, a * std::sqrt(3.0) / 6, a * std::sqrt(2.0 / 3.0)};
  const Vec3 proj = top + Vec3{0, 0, 2 * r + shift};
  Problem p;
  p.spheres = {Sphere{v0, rE, q, 15}, Sphere{v1, rE, -q, 15}, Sphere{v2, rE, q, 15},
               Sphere{top, rE, -q, 15}, Sphere{proj, rE, q, 15}};
  return p;
}

Vec3 reference_force(int ppp, double shift) {
  SolverOptions o;
  o.solver = "bem";
  o.patches_per_sphere = ppp;
  o.matvec = "direct";
  return make_bem_solver(o)->solve(five_spheres(shift)).force[4];
}

// Projectile displacement for the warm-start solve: 1 % of the 0.01 r electrostatic gap.
constexpr double kShift = 0.01 * 0.01 * 10e-6;

void BM_BemFiveSpheres(benchmark::State& st) {
  const bool fmm = st.range(0) == 1, warm = st.range(1) == 1;
  const int ppp = static_cast<int>(st.range(2));
  SolverOptions o;
  o.solver = "bem";
  o.patches_per_sphere = ppp;
  o.matvec = fmm ? "fmm" : "direct";
  Solution s;
  for (auto _ : st) {
    st.PauseTiming();
    auto solver = make_bem_solver(o);
    if (warm) solver->solve(five_spheres(0.0));
    st.ResumeTiming();
    s = solver->solve(five_spheres(warm ? kShift : 0.0));
  }
  const Vec3 ref = reference_force(ppp, warm ? kShift : 0.0);
  st.counters["ppp"] = ppp;
  st.counters["iters"] = s.stats.iterations;
  st.counters["matvecs"] = s.stats.extra["matvecs"].get<int>();
  st.counters["p_fmm"] = s.stats.extra["fmm_order"].get<int>();
  st.counters["Fz_proj_uN"] = s.force[4].z * 1e6;
  st.counters["rel_dF_vs_direct"] = norm(s.force[4] - ref) / norm(ref);
}

// Accuracy against docs/model.md §B.4 (two equal spheres, force on sphere 2 / F0) vs patches per sphere.
struct TableEntry {
  double kp, h, c1, c2, ref;
};
constexpr TableEntry kTable[] = {{10, 1, 1, 1, 0.0980225},   {10, 0.1, 1, -1, -0.494063},
                                 {10, 0.1, 1, 0, -0.0838583}, {2.5, 0.1, 1, 10, -0.358169},
                                 {10, 1, 1, 10, 0.369038},    {10, 0.1, 1, 10, -5.20623},
                                 {10, 0.01, 1, -1, -0.913658}};

void BM_BemTwoSphereAccuracy(benchmark::State& st) {
  const TableEntry& e = kTable[st.range(0)];
  const double R = 10e-6, Q0 = 1e-14, F0 = Q0 * Q0 / (4 * constants::pi * constants::eps0 * R * R);
  SolverOptions o;
  o.solver = "bem";
  o.patches_per_sphere = static_cast<int>(st.range(1));
  o.matvec = "direct";
  Problem p;
  p.spheres = {Sphere{{0, 0, 0}, R, e.c1 * Q0, e.kp}, Sphere{{(2 + e.h) * R, 0, 0}, R, e.c2 * Q0, e.kp}};
  Solution s;
  for (auto _ : st) s = make_bem_solver(o)->solve(p);
  st.counters["kp"] = e.kp;
  st.counters["h_over_R"] = e.h;
  st.counters["c2"] = e.c2;
  st.counters["ppp"] = o.patches_per_sphere;
  st.counters["F_over_F0"] = s.force[1].x / F0;
  st.counters["ref"] = e.ref;
  st.counters["rel_err"] = s.force[1].x / F0 / e.ref - 1.0;
  st.counters["iters"] = s.stats.iterations;
}

}  // namespace

BENCHMARK(BM_BemTwoSphereAccuracy)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5, 6}, {500, 1000, 2000, 4000}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime();
BENCHMARK(BM_BemFiveSpheres)
    ->ArgsProduct({{0, 1}, {0, 1}, {2000}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5)
    ->UseRealTime();
BENCHMARK_MAIN();
