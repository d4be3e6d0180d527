// DEM cost benchmarks (issue 2; docs/benchmarks_dem.md).
//
// BM_DemStep/N: one velocity-Verlet step of an adhesive agglomerate of N equal spheres (r = 10 um,
//   rho = 2500, JKR as docs/model.md §A.3, Marshall tangential spring) packed on a simple cubic lattice
//   with spacing 2r - delta0 (every lattice contact at the JKR equilibrium overlap), sites filled in
//   order, with random velocities of 1 mm/s (well below the sticking velocity, so contacts stay).
//   Counter "ns_per_particle_step" = wall time / (N x steps); it stays flat if the step is O(N).
//   Neighbour-list rebuilds are rare at these speeds; BM_NeighborBuild/N times one rebuild.
// BM_Collision2ms: one complete collision run of cases/seed000_neutral_tetrahedron_e0p9.toml
//   (5 particles, approach + 2 ms after first contact, break-up classification, no file output),
//   with the LAMMPS cross-check settings (break_rule = lammps, tangential = marshall). The LAMMPS
//   side of this comparison is bench/dem_benchmarks.sh.
//
// BM_DemBlock/N/reference: the block of BM_DemStep run for a fixed number of steps in one timed
//   iteration, as its LAMMPS twin (bench/lammps/block_case.py) runs it: AGGLO_BLOCK_WARM untimed steps
//   (default 200), then AGGLO_BLOCK_STEPS timed steps (default 1000) in block_steps(), which
//   bench/dem_block_vs_lammps.sh also counts instructions of (callgrind --toggle-collect). reference = 1
//   runs the reference twin of the DEM step (DemSystem::set_reference_kernel), 0 the fast path (eight pairs
//   at a time where the CPU has AVX-512, dem/contact/lanes.hpp), 2 the fast path four pairs at a time.
//   Counter "ns_per_particle_step" uses the process CPU time (all threads).
// BM_DemAggregateWall/N/reference: the second system of bench/dem_block_vs_lammps.sh, an N-primary fractal
//   aggregate hitting a wall, run like BM_DemBlock (AGGLO_BLOCK_WARM untimed + AGGLO_BLOCK_STEPS timed
//   steps in block_steps()). The aggregate is cases/breakage_wall_fractal.toml's (D_f = 1.8, k_f = 1.3,
//   seed 1, r = 10 um, e = 0.7) with agglomerate.primaries = N, built and scaled to the JKR equilibrium
//   overlap by agglo's structure builder (impact::build_agglomerate), with the LAMMPS cross-check's
//   contact settings (break_rule = lammps, tangential = marshall); every primary moves at 0.5 m/s along +x.
//   The wall is a frozen layer of spheres of the same radius and material (density kWallDensity, so
//   they do not move and m* of a contact is the primary's mass) on a square grid of spacing 2.6 r
//   (no wall-wall pair is listed, in agglo or LAMMPS) in the plane one tenth of a radius plus r beyond
//   the farthest primary surface, at every grid site within 2 r + 2.6 r of a primary's (y, z): LAMMPS'
//   fix wall/gran with jkr (29 Sep 2021) turns a sphere touching the wall into NaN, so both codes use
//   this layer. The first primary touches it after about 90 steps. Counter ns_per_particle_step divides
//   by every particle, primaries and wall spheres (LAMMPS' atom count). With AGGLO_AGGWALL_DUMP=path the
//   start state is written to that file for its LAMMPS twin (bench/lammps/aggregate_wall_case.py): a
//   header line "# dt primaries", then one line "x y z r density vx vy vz" per particle.
//
// Run single-threaded for per-core cost: OMP_NUM_THREADS=1 build-bench/bench_dem_scaling
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/core/config.hpp"
#include "agglo/dem/contact/lanes.hpp"
#include "agglo/dem/contact/marshall_sliding.hpp"
#include "agglo/dem/dem_system.hpp"
#include "agglo/dem/jkr.hpp"

namespace {

using agglo::Vec3;
namespace dem = agglo::dem;

dem::DemParams block_params() {
  dem::DemParams p;
  p.contact.youngs_modulus = 1.0e9;
  p.contact.poisson_ratio = 0.33;
  p.contact.surface_energy = 0.01;
  p.contact.restitution = 0.9;
  p.contact.friction = 0.3;
  p.contact.models.tangential = dem::contact::MarshallSliding::name;
  return p;
}

dem::DemSystem make_block(std::int64_t n) {
  const double r = 10e-6, rho = 2500.0;
  auto params = block_params();
  auto jkr = dem::JkrPair::make(0.5 * r, params.contact.estar(), params.contact.surface_energy);
  const double L = 2.0 * r - jkr.delta_equilibrium();
  const auto side = static_cast<std::int64_t>(std::ceil(std::cbrt(static_cast<double>(n)) - 1e-9));
  std::mt19937_64 gen(12345);
  std::normal_distribution<double> g(0.0, 1e-3 / std::sqrt(3.0));
  dem::Particles p;
  for (std::int64_t k = 0; k < n; ++k) {
    const std::int64_t ix = k % side, iy = (k / side) % side, iz = k / (side * side);
    p.add(Vec3{ix * L, iy * L, iz * L}, r, rho, Vec3{g(gen), g(gen), g(gen)});
  }
  return dem::DemSystem(std::move(p), params);
}

void BM_DemStep(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  auto sys = make_block(n);
  sys.run(200);  // form contacts, build the list, warm the caches
  for (auto _ : state) sys.step();
  state.counters["particles"] = static_cast<double>(n);
  state.counters["contacts"] = sys.active_contacts();
  state.counters["pairs_listed"] = static_cast<double>(sys.pairs().size());
  state.counters["list_builds"] = static_cast<double>(sys.neighbors().builds());
  // rate counter inverted: seconds per (N * 1e-9) items = ns per particle-step
  state.counters["ns_per_particle_step"] =
      benchmark::Counter(static_cast<double>(n) * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                            benchmark::Counter::kInvert);
}
BENCHMARK(BM_DemStep)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

long env_steps(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v ? std::atol(v) : fallback;
}

// The timed steps of BM_DemBlock (a function of its own: callgrind counts its instructions alone).
[[gnu::noinline]] void block_steps(dem::DemSystem& sys, long steps) { sys.run(steps); }

// AGGLO_BLOCK_WARM untimed steps, then AGGLO_BLOCK_STEPS timed steps of sys (kernel: state.range(1)); its
// name must not match callgrind's --toggle-collect='*block_steps*' (a nested match toggles collection off);
// counters contacts, steps and ns_per_particle_step (CPU time / (particles x steps)).
void timed_steps_of(benchmark::State& state, dem::DemSystem& sys) {
  const long warm = env_steps("AGGLO_BLOCK_WARM", 200), steps = env_steps("AGGLO_BLOCK_STEPS", 1000);
  sys.set_reference_kernel(state.range(1) == 1);
  dem::contact::lanes::set_wide_lanes(state.range(1) == 0);
  sys.run(warm);
  for (auto _ : state) block_steps(sys, steps);
  state.counters["contacts"] = sys.active_contacts();
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["ns_per_particle_step"] =
      benchmark::Counter(static_cast<double>(sys.particles().size()) * static_cast<double>(steps) * 1e-9,
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["wide_lanes"] = dem::contact::lanes::wide_lanes();
  dem::contact::lanes::set_wide_lanes(true);
}

void BM_DemBlock(benchmark::State& state) {
  auto sys = make_block(state.range(0));
  timed_steps_of(state, sys);
}
BENCHMARK(BM_DemBlock)
    ->ArgsProduct({{1000, 10000, 100000}, {0, 1, 2}})
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

constexpr double kWallDensity = 1e30;  // kg/m^3: a frozen wall sphere (BM_DemAggregateWall)

// The frozen wall layer of BM_DemAggregateWall in front of the primaries of p (appended to p).
void add_wall_layer(dem::Particles& p, double rho) {
  const double r = p.r[0], s = 2.6 * r, reach = 2.0 * r + s;
  const std::size_t n = p.size();
  double xmax = -1e300, ylo = 1e300, yhi = -1e300, zlo = 1e300, zhi = -1e300;
  for (std::size_t k = 0; k < n; ++k) {
    xmax = std::max(xmax, p.x[k].x + p.r[k]);
    ylo = std::min(ylo, p.x[k].y), yhi = std::max(yhi, p.x[k].y);
    zlo = std::min(zlo, p.x[k].z), zhi = std::max(zhi, p.x[k].z);
  }
  const auto lo = [&](double v) { return static_cast<long>(std::floor((v - reach) / s)); };
  const auto hi = [&](double v) { return static_cast<long>(std::ceil((v + reach) / s)); };
  for (long j = lo(ylo); j <= hi(yhi); ++j)
    for (long k = lo(zlo); k <= hi(zhi); ++k) {
      const double y = j * s, z = k * s;
      bool near = false;
      for (std::size_t q = 0; q < n && !near; ++q)
        near = (p.x[q].y - y) * (p.x[q].y - y) + (p.x[q].z - z) * (p.x[q].z - z) < reach * reach;
      if (near) p.add(Vec3{xmax + 0.1 * r + r, y, z}, r, rho);
    }
}

// The aggregate of BM_DemAggregateWall and its wall layer (written to AGGLO_AGGWALL_DUMP if set).
dem::DemSystem make_aggregate_wall(std::int64_t primaries) {
  const std::filesystem::path src = AGGLO_SOURCE_DIR;
  auto cfg = agglo::Config::load(src / "cases" / "breakage_wall_fractal.toml");
  const std::string n = "agglomerate.primaries=" + std::to_string(primaries);
  for (const char* s : {n.c_str(), "contact.break_rule=lammps", "contact.tangential=marshall",
                        "wall.position=[5e-3, 0.0, 0.0]"})  // the wall is the layer of add_wall_layer
    cfg.apply_override(s);
  auto c = agglo::impact::parse_impact_case(cfg);
  c.dem.walls.clear();
  dem::Particles p = agglo::impact::build_agglomerate(c);
  const double speed = 0.5, rho = agglo::impact::material_density(c, 0);
  for (auto& v : p.v) v = Vec3{speed, 0.0, 0.0};
  add_wall_layer(p, kWallDensity);
  dem::DemSystem sys(p, c.dem);
  if (const char* dump = std::getenv("AGGLO_AGGWALL_DUMP")) {
    std::ofstream out(dump);
    out.precision(17);
    out << "# " << sys.dt() << ' ' << primaries << '\n';
    for (std::size_t k = 0; k < p.size(); ++k)
      out << p.x[k].x << ' ' << p.x[k].y << ' ' << p.x[k].z << ' ' << p.r[k] << ' '
          << (k < static_cast<std::size_t>(primaries) ? rho : kWallDensity) << ' ' << p.v[k].x << ' ' << p.v[k].y
          << ' ' << p.v[k].z << '\n';
  }
  return sys;
}

void BM_DemAggregateWall(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  auto sys = make_aggregate_wall(n);
  timed_steps_of(state, sys);
  int wall_contacts = 0;  // contacts of a primary with a wall sphere
  for (const auto& pr : sys.pairs()) wall_contacts += pr.state.active && (pr.i >= n) != (pr.j >= n);
  state.counters["particles"] = static_cast<double>(sys.particles().size());
  state.counters["wall_contacts"] = wall_contacts;
  state.counters["ke_end"] = sys.translational_kinetic_energy();  // [J], LAMMPS' ke after the same steps
}
BENCHMARK(BM_DemAggregateWall)
    ->ArgsProduct({{100, 1000}, {0, 1, 2}})
    ->Iterations(1)
    ->MeasureProcessCPUTime()
    ->Unit(benchmark::kMillisecond);

void BM_NeighborBuild(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  auto sys = make_block(n);
  sys.run(10);
  const auto& p = sys.particles();
  auto params = block_params();
  const double skin = 0.1 * p.r[0];
  for (auto _ : state) {
    dem::NeighborList nl;
    nl.build(p.x, p.r, skin, [&](dem::Pair& pr) {
      pr.jkr = dem::JkrPair::make(p.r[pr.i] * p.r[pr.j] / (p.r[pr.i] + p.r[pr.j]), params.contact.estar(),
                                  params.contact.surface_energy);
    });
    benchmark::DoNotOptimize(nl.pairs().data());
  }
  state.counters["ns_per_particle"] =
      benchmark::Counter(static_cast<double>(n) * 1e-9, benchmark::Counter::kIsIterationInvariantRate |
                                                            benchmark::Counter::kInvert);
}
BENCHMARK(BM_NeighborBuild)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_Collision2ms(benchmark::State& state) {
  const std::filesystem::path src = AGGLO_SOURCE_DIR;  // the source tree (CMakeLists.txt)
  auto cfg = agglo::Config::load(src / "cases" / "seed000_neutral_tetrahedron_e0p9.toml");
  for (const char* s : {"contact.break_rule=lammps", "contact.tangential=marshall", "material.restitution=0.9",
                        "material.friction=0.3", "time.early_stop=false"})  // full 2 ms, as LAMMPS
    cfg.apply_override(s);
  auto c = agglo::impact::parse_impact_case(cfg);
  const double speed = 0.18;
  long steps = 0;
  bool broken = false;
  for (auto _ : state) {
    auto out = agglo::impact::run_impact(c, speed, nullptr);
    steps = out.steps;
    broken = out.broken;
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["broken"] = broken ? 1.0 : 0.0;
  state.counters["ns_per_step"] = benchmark::Counter(
      static_cast<double>(steps) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Collision2ms)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
