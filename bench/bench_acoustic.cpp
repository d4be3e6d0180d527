// Benchmarks of the DSMC acoustic engine (issue 4):
//  - BM_AcousticStep/N: one collision step (exact motion + binning + Nanbu) of a seed-002 baseline-like
//    state (98 % lognormal fines, 2 % 30 um droplets, ~84 samples per cell) with N sampled particles;
//    reports ns per sampled particle per step (should be flat in N: O(N)).
//  - BM_AdditiveKernel1e5: Smoluchowski additive kernel, exponential start, 1e5 samples to tau = 1
//    (200 steps), the case of tests/acoustics/test_smoluchowski.cpp (cf. PartMC's additive test, ~9 s).
//  - BM_BaselineCase: cases/seed002_baseline.toml as shipped (8403 samples, 4 s of simulated time),
//    one iteration; set AGGLO_BENCH_BASELINE_END to shorten it (e.g. 0.4 s, then scale by 10).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "agglo/acoustics/case_config.hpp"
#include "agglo/acoustics/engine.hpp"
#include "agglo/core/config.hpp"

using namespace agglo::acoustics;

namespace {

Engine make(const std::string& toml) {
  agglo::Config cfg = agglo::Config::from_string(toml, "bench.toml");
  return Engine(parse_acoustic_case(cfg).engine);
}

std::string baseline_like(long n) {
  // Keep ~84 samples per cell: 100 cells along x, then refine y and z.
  const long cells = std::max<long>(100, n / 84);
  const int cyz = static_cast<int>(std::max(1.0, std::round(std::sqrt(cells / 100.0))));
  const long fines = n - n / 50, drops = n / 50;
  return fmt::format(R"(
seed = 1
[sound]
level_db = 140.0
frequency_hz = 2000.0
[domain]
cells_x = 100
cells_y = {0}
cells_z = {0}
[time]
end = 1.0
collision_dt = 1e-5
[[population]]
name = "fines"
phase = "solid"
distribution = "lognormal"
geometric_mean_diameter = 0.2e-6
geometric_std = 2.0
bins = 40
number_concentration = 5e11
samples = {1}
[[population]]
name = "droplets"
phase = "liquid"
distribution = "monodisperse"
diameter = 30e-6
number_concentration = 1e9
samples = {2}
)",
                     cyz, fines, drops);
}

void BM_AcousticStep(benchmark::State& st) {
  const long n = st.range(0);
  Engine e = make(baseline_like(n));
  for (int k = 0; k < 3; ++k) e.step();  // warm up
  for (auto _ : st) e.step();
  st.SetItemsProcessed(st.iterations() * n);
  st.counters["ns_per_particle_step"] = benchmark::Counter(
      static_cast<double>(st.iterations() * n) * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_AcousticStep)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_AdditiveKernel1e5(benchmark::State& st) {
  const double N0 = 1048576.0 * 1e5, v0 = 1e-18;
  const std::string toml = fmt::format(R"(
seed = 11
[gas]
gravity = false
[sound]
enabled = false
[domain]
length_x = 1.0
length_y = 1.0
length_z = 1.0
cells_x = 1
[time]
end = 1.0
collision_dt = 0.005
integrator = "none"
[[population]]
name = "exp"
phase = "solid"
distribution = "exponential"
mean_volume = {}
number_concentration = {}
samples = 100000
[kernels]
model = "additive"
additive_coefficient = {}
[outcomes]
always_coalesce = true
)",
                                       v0, N0, 1.0 / (N0 * v0));
  for (auto _ : st) {
    Engine e = make(toml);
    while (e.time() < 1.0 - 1e-9) e.step();
    benchmark::DoNotOptimize(e.stats().collisions);
  }
}
BENCHMARK(BM_AdditiveKernel1e5)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void BM_BaselineCase(benchmark::State& st) {
  agglo::Config cfg = agglo::Config::load(std::filesystem::path(AGGLO_SOURCE_DIR) / "cases" / "seed002_baseline.toml");
  if (const char* e = std::getenv("AGGLO_BENCH_BASELINE_END")) {
    cfg.apply_override(std::string("time.end=") + e);
    cfg.apply_override("output.psd_times=[0.0]");
    cfg.apply_override("output.snapshot_times=[0.0]");
  }
  const AcousticCase c = parse_acoustic_case(cfg);
  for (auto _ : st) {
    Engine e(c.engine);
    const auto n = e.total_steps();
    for (std::uint64_t s = 0; s < n; ++s) e.step();
    st.counters["fine_efficiency_proxy_collisions"] = static_cast<double>(e.stats().collisions);
    st.counters["simulated_s"] = e.time();
  }
}
BENCHMARK(BM_BaselineCase)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
