// FMM vs direct Laplace sum (potential + field) for 1e3 .. 1e6 random points in a cube and on
// sphere surfaces. Counters: N, order p, relative field error (2-norm over 1000 sampled targets,
// against the direct sum for those targets), M2L pairs. The direct sum is timed up to 1e5
// points (O(N^2); extrapolate above). Orders: p = 10 for the scaling series and an
// order sweep at 1e5 surface points. Run:
//   OMP_NUM_THREADS=2 ./bench_fmm --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "agglo/core/constants.hpp"
#include "agglo/electrostatics/fmm/direct.hpp"
#include "agglo/electrostatics/fmm/fmm.hpp"

using namespace agglo;
using namespace agglo::es::fmm;

namespace {

// kind 0: uniform in the unit cube; kind 1: Fibonacci points on a row of near-touching spheres
// (1e4 points per sphere) -- the BEM geometry.
std::vector<Vec3> make_points(int n, int kind) {
  std::vector<Vec3> p(n);
  std::mt19937_64 g(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  if (kind == 0) {
    for (auto& x : p) x = {u(g), u(g), u(g)};
    return p;
  }
  const int per = std::min(n, 10000);
  const double ga = constants::pi * (3.0 - std::sqrt(5.0));
  const int ns = (n + per - 1) / per;
  const int side = static_cast<int>(std::ceil(std::cbrt(ns)));
  for (int i = 0; i < n; ++i) {
    const int s = i / per, k = i % per;
    const Vec3 c{2.02 * (s % side), 2.02 * ((s / side) % side), 2.02 * (s / (side * side))};
    const double z = 1.0 - (2.0 * k + 1.0) / per, rho = std::sqrt(1 - z * z);
    p[i] = c + Vec3{rho * std::cos(ga * k), rho * std::sin(ga * k), z};
  }
  return p;
}

std::vector<double> make_charges(int n) {
  std::vector<double> q(n);
  std::mt19937_64 g(777);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (auto& x : q) x = u(g);
  return q;
}

// Relative field error at 1000 sampled targets.
double sampled_error(const std::vector<Vec3>& pts, const std::vector<double>& q, const std::vector<Vec3>& e) {
  const std::size_t stride = std::max<std::size_t>(1, pts.size() / 1000);
  std::vector<Vec3> tg;
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < pts.size(); i += stride) {
    tg.push_back(pts[i]);
    idx.push_back(i);
  }
  std::vector<Vec3> ref;
  direct_sum(tg, pts, q, nullptr, &ref);
  double d = 0, r = 0;
  for (std::size_t k = 0; k < idx.size(); ++k) {
    d += norm2(e[idx[k]] - ref[k]);
    r += norm2(ref[k]);
  }
  return std::sqrt(d / r);
}

void BM_Fmm(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0)), p = static_cast<int>(st.range(1)), kind = static_cast<int>(st.range(2));
  const auto pts = make_points(n, kind);
  const auto q = make_charges(n);
  FmmOptions o;
  o.order = p;
  std::vector<Vec3> e;
  std::vector<double> phi;
  std::size_t m2l = 0;
  for (auto _ : st) {
    LaplaceFmm f(pts, o);  // tree + lists included in the timing
    f.evaluate(q, &phi, &e);
    m2l = f.lists().n_m2l;
  }
  st.counters["N"] = n;
  st.counters["p"] = p;
  st.counters["m2l"] = static_cast<double>(m2l);
  st.counters["err"] = sampled_error(pts, q, e);
}

void BM_Direct(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0)), kind = static_cast<int>(st.range(1));
  const auto pts = make_points(n, kind);
  const auto q = make_charges(n);
  std::vector<Vec3> e;
  std::vector<double> phi;
  for (auto _ : st) direct_sum(pts, pts, q, &phi, &e);
  st.counters["N"] = n;
}

// The BEM's direct matvec: the normal-field kernel, row by row (each pair evaluated from both ends).
void BM_DirectNormal(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const auto pts = make_points(n, 1);
  const auto q = make_charges(n);
  std::vector<Vec3> nrm(n);
  for (int i = 0; i < n; ++i) nrm[i] = pts[i] / norm(pts[i]);
  const Points P(pts), Nn(nrm);
  std::vector<double> y(n);
  for (auto _ : st) direct_normal_field(P, Nn, q, y);
  st.counters["N"] = n;
}

// Scaling at p = 10 on surfaces (the BEM geometry, up to 1e6) and in a volume (up to 1e5: with
// theta = 0.4 a volume cell has ~2e3 M2L partners, so volumes are M2L bound); order sweep at 1e5.
void fmm_args(benchmark::internal::Benchmark* b) {
  for (int n : {1000, 3000, 10000, 30000, 100000, 300000, 1000000}) b->Args({n, 10, 1});
  for (int n : {1000, 3000, 10000, 30000, 100000}) b->Args({n, 10, 0});
  for (int p : {4, 8, 12, 16}) b->Args({100000, p, 1});
}

}  // namespace

BENCHMARK(BM_Fmm)->Apply(fmm_args)->Unit(benchmark::kMillisecond)->MinTime(0.3)->UseRealTime();
BENCHMARK(BM_Direct)
    ->ArgsProduct({{1000, 3000, 10000, 30000, 100000}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.3)
    ->UseRealTime();
BENCHMARK(BM_DirectNormal)
    ->Arg(1000)->Arg(3000)->Arg(10000)->Arg(30000)->Arg(100000)
    ->Unit(benchmark::kMillisecond)->MinTime(0.3)->UseRealTime();
BENCHMARK_MAIN();
