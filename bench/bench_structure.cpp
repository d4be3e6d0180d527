// Structure builder (src/agglo/structure): wall time of one aggregate of N primaries, fractal (D_f 1.8,
// k_f 1.3, monodisperse and sigma_g = 1.5), BPCA and BCCA; the issue asks for a 1000-primary fractal
// aggregate in under a second on one core. Each iteration builds with another seed. Run:
//   ./bench_structure --benchmark_filter=Fractal
// and for the instruction count: valgrind --tool=callgrind ./bench_structure
//   --benchmark_filter=Fractal/1000/1 --benchmark_min_time=0.01   (docs/model.md, structure builder)
#include <benchmark/benchmark.h>

#include <cstdint>

#include "agglo/structure/ballistic.hpp"
#include "agglo/structure/fractal.hpp"

using namespace agglo::structure;

namespace {

void Fractal(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double sigma_g = state.range(1) == 1 ? 1.0 : 1.5;
  std::uint64_t seed = 1;
  for (auto _ : state) {
    const Aggregate a = build_fractal({.primaries = n, .radius = 1.0, .radius_std = sigma_g, .seed = seed++});
    benchmark::DoNotOptimize(a.x.data());
  }
  state.counters["N"] = n;
}
BENCHMARK(Fractal)->Args({1000, 1})->Args({1000, 2})->Args({256, 1})->Unit(benchmark::kMillisecond);

void BallisticBuild(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto kind = state.range(1) == 0 ? Ballistic::particle_cluster : Ballistic::cluster_cluster;
  std::uint64_t seed = 1;
  for (auto _ : state) {
    const Aggregate a = build_ballistic({.kind = kind, .primaries = n, .radius = 1.0, .seed = seed++});
    benchmark::DoNotOptimize(a.x.data());
  }
  state.counters["N"] = n;
}
BENCHMARK(BallisticBuild)->Args({1000, 0})->Args({1024, 1})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
