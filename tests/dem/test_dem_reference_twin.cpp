// The fast DEM pair step against its reference twin (DemSystem::set_reference_kernel; issue 27). The reference
// evaluates every pair with the kernel of d26cae2 (Newton from the last radius to convergence) into a per-pair
// buffer and gathers it per particle; the fast path adds each pair's force straight into the particles with the
// fast contact radius (jkr_root_fast: no warm start, no convergence test) and one 1/|d|. Their results differ in
// the last bits, so they are compared against the documented DEM output tolerance (docs/benchmarks_dem.md §8:
// positions, velocities, kinetic energy, contact counts) on an adhesive block at JKR equilibrium and on an
// impact that forms and breaks contacts on a wall, with a negative control (a contact radius wrong by a part in
// 1e9 must fail it). The fast path on several threads (pair blocks, the fused parallel step, the thread-count
// probes) must equal the fast path on one thread bit for bit (thread-count invariance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <omp.h>
#include <random>
#include <string>

#include "agglo/dem/contact/marshall_rolling.hpp"
#include "agglo/dem/contact/marshall_sliding.hpp"
#include "agglo/dem/contact/marshall_twisting.hpp"
#include "agglo/dem/dem_system.hpp"
#include "agglo/dem/parallel_for.hpp"

using namespace agglo;
using namespace agglo::dem;

namespace {

constexpr double kTwinR = 10e-6, kTwinRho = 2500.0;

DemParams twin_params(bool all_models) {
  DemParams p;
  p.contact.youngs_modulus = 1.0e9;
  p.contact.poisson_ratio = 0.33;
  p.contact.surface_energy = 0.01;
  p.contact.restitution = 0.7;
  p.contact.friction = 0.3;
  if (all_models) {
    p.contact.models.tangential = contact::MarshallSliding::name;
    p.contact.models.rolling = contact::MarshallRolling::name;
    p.contact.models.twisting = contact::MarshallTwisting::name;
  }
  return p;
}

// side^3 spheres on a simple cubic lattice of spacing 2r - delta0, random velocities of `speed`.
Particles twin_block(int side, double speed) {
  const auto p = twin_params(false);
  const double L = 2.0 * kTwinR - JkrPair::make(0.5 * kTwinR, p.contact.estar(), p.contact.surface_energy).delta_equilibrium();
  std::mt19937_64 gen(7);
  std::normal_distribution<double> g(0.0, speed / std::sqrt(3.0));
  Particles out;
  for (int k = 0; k < side * side * side; ++k)
    out.add(Vec3{(k % side) * L, (k / side % side) * L, (k / (side * side)) * L}, kTwinR, kTwinRho,
            Vec3{g(gen), g(gen), g(gen)});
  return out;
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// Number of differing particle or pair fields (0: the two systems are bit for bit equal).
int twin_differences(const DemSystem& a, const DemSystem& b) {
  int bad = 0;
  const auto& p = a.particles();
  const auto& q = b.particles();
  for (std::size_t k = 0; k < p.size(); ++k)
    bad += !same_bits(p.x[k], q.x[k]) + !same_bits(p.v[k], q.v[k]) + !same_bits(p.w[k], q.w[k]) +
           !same_bits(p.f[k], q.f[k]) + !same_bits(p.t[k], q.t[k]);
  if (a.pairs().size() != b.pairs().size()) return bad + 1;
  for (std::size_t k = 0; k < a.pairs().size(); ++k) {
    const auto &s = a.pairs()[k].state, &t = b.pairs()[k].state;
    bad += (s.active != t.active) + !same_bits(s.a, t.a) + !same_bits(s.xi_t, t.xi_t) + !same_bits(s.xi_r, t.xi_r) +
           !same_bits(s.xi_q, t.xi_q);
  }
  return bad;
}

// The largest deviations of system a from system b (the documented tolerance, docs/benchmarks_dem.md §8): positions
// relative to the particle's radius, velocities relative to b's largest speed, the kinetic energy relative to b's,
// and the difference of the contact counts (particle pairs and walls).
struct Deviation {
  double x = 0.0, v = 0.0, ke = 0.0;
  int contacts = 0;
};

Deviation deviation(const DemSystem& a, const DemSystem& b) {
  Deviation d;
  const auto& p = a.particles();
  const auto& q = b.particles();
  double vmax = 0.0;
  for (std::size_t k = 0; k < q.size(); ++k) vmax = std::max(vmax, norm(q.v[k]));
  for (std::size_t k = 0; k < p.size(); ++k) {
    d.x = std::max(d.x, norm(p.x[k] - q.x[k]) / q.r[k]);
    d.v = std::max(d.v, norm(p.v[k] - q.v[k]) / vmax);
  }
  d.ke = std::abs(a.kinetic_energy() - b.kinetic_energy()) / b.kinetic_energy();
  d.contacts = std::abs(a.active_contacts() - b.active_contacts()) + std::abs(a.wall_contacts() - b.wall_contacts());
  return d;
}

// The documented tolerance of the fast path against the reference twin (docs/benchmarks_dem.md §8).
constexpr double kTolX = 1e-12, kTolV = 1e-9, kTolKe = 1e-10;

bool within_tolerance(const Deviation& d) { return d.x <= kTolX && d.v <= kTolV && d.ke <= kTolKe && d.contacts == 0; }

std::string describe(const Deviation& d) {
  return "positions " + std::to_string(d.x * 1e15) + "e-15 r, velocities " + std::to_string(d.v * 1e12) +
         "e-12 v_max, kinetic energy " + std::to_string(d.ke * 1e15) + "e-15, contact counts " +
         std::to_string(d.contacts);
}

// The fast path on one thread (the comparator of the multi-thread runs: the same bits at any thread count).
DemSystem one_thread_fast(DemSystem sys, long steps) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  sys.run(steps);
  omp_set_num_threads(saved);
  return sys;
}

// AGGLO_THREAD_PROBE=off for the guard's lifetime: DemSystem::step keeps the whole team at every step (no
// probes at one thread, core/thread_choice.hpp), so that a test of the parallel path runs it throughout.
struct FixedThreadCount {
  FixedThreadCount() { setenv("AGGLO_THREAD_PROBE", "off", 1); }
  ~FixedThreadCount() { unsetenv("AGGLO_THREAD_PROBE"); }
};

}  // namespace

// The block at JKR equilibrium (every contact static, the Newton warm start of the reference at its best), both
// model sets, 300 steps: within the tolerance at every 50 steps. Negative control: the fast path with a surface
// energy larger by 1e-9 (contact radii a0 ~ gamma^(1/3) wrong by 3e-10; the same dt) leaves it.
TEST(DemReferenceTwin, BlockAtEquilibriumWithinTolerance) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);  // the fast path runs on one thread
  for (bool all_models : {false, true}) {
    DemSystem fast(twin_block(5, 1e-3), twin_params(all_models));
    DemSystem ref(twin_block(5, 1e-3), twin_params(all_models));
    auto wrong_params = twin_params(all_models);
    wrong_params.contact.surface_energy *= 1.0 + 1e-9;
    wrong_params.dt = fast.dt();  // (the same step: dt = T0 / 50 depends on gamma)
    DemSystem wrong(twin_block(5, 1e-3), wrong_params);
    ref.set_reference_kernel(true);
    EXPECT_FALSE(fast.reference_kernel());
    for (int chunk = 0; chunk < 6; ++chunk) {
      fast.run(50);
      ref.run(50);
      wrong.run(50);
      const Deviation d = deviation(fast, ref);
      std::printf("block, all models %d, step %ld: %s\n", all_models, fast.steps(), describe(d).c_str());
      ASSERT_TRUE(within_tolerance(d)) << "step " << fast.steps() << ", all models " << all_models << ": " << describe(d);
    }
    EXPECT_GT(deviation(fast, ref).x, 0.0);  // (the paths do differ: the comparison is not of equal bits)
    const Deviation w = deviation(wrong, ref);
    std::printf("block, all models %d, control (gamma + 1e-9): %s\n", all_models, describe(w).c_str());
    EXPECT_FALSE(within_tolerance(w)) << "control: " << describe(w);
    EXPECT_EQ(fast.active_contacts(), 300);  // 3 * 5 * 5 * 4 lattice contacts, all kept
  }
  omp_set_num_threads(saved);
}

// The parallel fast path (blocks of pairs, contact/pair_blocks.hpp: more than one thread and more than
// kParallelThreshold pairs) against the fast path on one thread: a 13^3 block (6084 lattice contacts),
// every particle moving, so that contacts also form and break; 2 and 3 threads (uneven blocks).
TEST(DemReferenceTwin, ParallelBlocksBitIdentical) {
  const FixedThreadCount fixed;
  const int saved = omp_get_max_threads();
  const DemSystem ref = one_thread_fast(DemSystem(twin_block(13, 0.05), twin_params(true)), 60);
  for (int threads : {2, 3}) {
    omp_set_num_threads(threads);
    DemSystem fast(twin_block(13, 0.05), twin_params(true));
    fast.run(60);
    ASSERT_GT(static_cast<std::int64_t>(fast.pairs().size()), kParallelThreshold);
    ASSERT_TRUE(runs_parallel(static_cast<std::int64_t>(fast.pairs().size())));
    EXPECT_EQ(twin_differences(fast, ref), 0) << threads << " threads";
    const auto blocks = contact::make_pair_blocks(fast.pairs(), fast.particles().size(), threads);
    EXPECT_GT(blocks.crossing.size(), 0u);  // (pairs between the blocks exist: the buffered path was taken)
  }
  omp_set_num_threads(saved);
}

// The neighbour list's rebuild test folded into the parallel drift loop (DemSystem::step, parallel_any_ranges and kick_drift.hpp)
// against the reference twin on one thread, which tests in needs_rebuild's serial pass (it fails when the
// folded test never asks for a rebuild: 1 build against 6), and every bit against the fast path on one
// thread: a 17^3 block (4913 particles, above kParallelThreshold: the drift loop runs on the team) fast enough
// that the list is rebuilt during the run (not vacuous: more builds than the first), 2 and 3 threads.
TEST(DemReferenceTwin, RebuildTestInTheParallelDriftBitIdentical) {
  const FixedThreadCount fixed;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  DemSystem ref(twin_block(17, 2.0), twin_params(true));
  ref.set_reference_kernel(true);
  ref.run(40);
  ASSERT_GT(ref.neighbors().builds(), 2);
  const DemSystem one = one_thread_fast(DemSystem(twin_block(17, 2.0), twin_params(true)), 40);
  for (int threads : {2, 3}) {
    omp_set_num_threads(threads);
    DemSystem fast(twin_block(17, 2.0), twin_params(true));
    fast.run(40);
    ASSERT_TRUE(runs_parallel(static_cast<std::int64_t>(fast.particles().size())));
    EXPECT_EQ(fast.neighbors().builds(), ref.neighbors().builds()) << threads << " threads";
    EXPECT_EQ(twin_differences(fast, one), 0) << threads << " threads";
  }
  omp_set_num_threads(saved);
}

// The parallel step with the forces it adds after its region (a wall and gravity: DemSystem::parallel_step's
// closing kick after the region) and the exact gas-drag kick: a 13^3 block (more than kParallelThreshold
// pairs) with its particles moving, dragged by a gas flow and pulled onto a wall it touches, on 2 and 3 threads against
// the fast path on one thread, every bit (it fails when the wall forces are left out of the parallel step).
TEST(DemReferenceTwin, ParallelStepWithWallGravityAndDragBitIdentical) {
  const FixedThreadCount fixed;
  const int saved = omp_get_max_threads();
  auto make = [](bool reference) {
    auto prm = twin_params(true);
    prm.gravity = Vec3{0.0, 0.0, -2.0e4};
    prm.gas.enabled = true;
    prm.gas.viscosity = 1.8e-5;
    prm.gas.mean_free_path = 68e-9;
    prm.gas.flow = Vec3{0.05, 0.0, 0.0};
    prm.walls.push_back(Wall{Vec3{0.0, 0.0, -0.999 * kTwinR}, Vec3{0.0, 0.0, 1.0}});
    DemSystem sys(twin_block(13, 0.05), prm);
    sys.set_reference_kernel(reference);
    return sys;
  };
  const DemSystem ref = one_thread_fast(make(false), 120);
  ASSERT_GT(ref.wall_contacts(), 0);  // (the wall was touched)
  for (int threads : {2, 3}) {
    omp_set_num_threads(threads);
    DemSystem fast = make(false);
    fast.run(120);
    ASSERT_TRUE(runs_parallel(static_cast<std::int64_t>(fast.pairs().size())));
    EXPECT_EQ(twin_differences(fast, ref), 0) << threads << " threads";
  }
  omp_set_num_threads(saved);
}

// The blocks own about equal numbers of pairs with both particles inside (phase 2 of the parallel pair step
// is balanced; the crossing pairs are spread evenly in phase 1): on the 13^3 block after 60 steps, 2 to 4
// blocks own counts within 1 % of their mean, against the split by pair count alone (the blocks of
// pairs [t np / B, (t+1) np / B)), whose first block owns C_0 fewer than its pairs (the negative control).
TEST(DemReferenceTwin, PairBlocksOwnEqualShares) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  DemSystem sys(twin_block(13, 0.05), twin_params(true));
  sys.run(60);
  omp_set_num_threads(saved);
  const auto& pairs = sys.pairs();
  for (std::size_t nb : {2u, 3u, 4u}) {
    const auto b = contact::make_pair_blocks(pairs, sys.particles().size(), nb);
    ASSERT_EQ(b.blocks(), nb);
    std::vector<double> own(nb, 0.0);
    for (std::size_t t = 0; t < nb; ++t)
      for (std::size_t k = b.first_pair[t]; k < b.first_pair[t + 1]; ++k) own[t] += pairs[k].j < b.first_particle[t + 1];
    const double mean = static_cast<double>(pairs.size() - b.crossing.size()) / static_cast<double>(nb);
    for (std::size_t t = 0; t < nb; ++t) EXPECT_NEAR(own[t], mean, 0.01 * mean) << nb << " blocks, block " << t;
    // The split by pair count: block 0 = pairs [0, np / nb) ends at the particle of pair np / nb.
    const std::uint32_t end0 = pairs[pairs.size() / nb].i;
    double own0 = 0.0;
    for (const Pair& pr : pairs) own0 += pr.i < end0 && pr.j < end0;
    EXPECT_GT(std::abs(own0 - mean), 0.02 * mean) << nb << " blocks (the control is not balanced)";
  }
}

// The thread count chosen per step by timed probes (DemSystem::step, core/thread_choice.hpp): the first
// kProbeSteps steps run on the whole team, the next kProbeSteps on one thread, then the faster count; a
// 13^3 block on 2 threads for 3 kProbeSteps steps has taken both counts (whatever the timings), and every
// bit equals the fast path's on one thread.
TEST(DemReferenceTwin, StepsOfBothThreadCountsBitIdentical) {
  const int saved = omp_get_max_threads();
  const long steps = 3 * static_cast<long>(ThreadChoice::kProbeSteps);
  const DemSystem ref = one_thread_fast(DemSystem(twin_block(13, 0.05), twin_params(true)), steps);
  omp_set_num_threads(2);
  DemSystem fast(twin_block(13, 0.05), twin_params(true));
  fast.run(steps);
  omp_set_num_threads(saved);
  EXPECT_GE(fast.thread_choice().steps_at_one(), ThreadChoice::kProbeSteps);  // (the third kProbeSteps: either)
  EXPECT_GE(fast.thread_choice().steps_at_max(), ThreadChoice::kProbeSteps);
  EXPECT_EQ(fast.thread_choice().steps_at_max() + fast.thread_choice().steps_at_one(), static_cast<std::uint64_t>(steps));
  EXPECT_EQ(twin_differences(fast, ref), 0);
}

// A projectile at 2 m/s into a 27-sphere block pushed onto a wall (2000 steps; contacts form and break, wall
// contacts too): within the tolerance at every 100 steps; the control with a surface energy larger by 1e-9 leaves
// it (at the same dt).
TEST(DemReferenceTwin, ImpactOnWallWithinTolerance) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  auto make = [](bool reference, double gamma_factor, double dt) {
    Particles p = twin_block(3, 0.0);
    double xmax = 0.0;
    for (const auto& x : p.x) xmax = std::max(xmax, x.x);
    p.add(Vec3{-3.0 * kTwinR, 0.3 * kTwinR, 0.2 * kTwinR}, kTwinR, kTwinRho, Vec3{2.0, 0.0, 0.0});  // projectile
    auto prm = twin_params(true);
    prm.contact.surface_energy *= gamma_factor;
    prm.dt = dt;
    prm.walls.push_back(Wall{Vec3{xmax + 1.2 * kTwinR, 0.0, 0.0}, Vec3{-1.0, 0.0, 0.0}});
    DemSystem sys(std::move(p), prm);
    sys.set_reference_kernel(reference);
    return sys;
  };
  DemSystem fast = make(false, 1.0, 0.0), ref = make(true, 1.0, 0.0), wrong = make(false, 1.0 + 1e-9, fast.dt());
  int most = 0, least = 1 << 30, wall_max = 0;
  bool control_left = false;
  for (int s = 1; s <= 2000; ++s) {
    fast.step();
    ref.step();
    wrong.step();
    if (s % 100 == 0) {
      const Deviation d = deviation(fast, ref), w = deviation(wrong, ref);
      std::printf("impact, step %d: %s; control: %s\n", s, describe(d).c_str(), describe(w).c_str());
      ASSERT_TRUE(within_tolerance(d)) << "step " << s << ": " << describe(d);
      control_left = control_left || !within_tolerance(w);
    }
    most = std::max(most, fast.active_contacts());
    if (most > 54) least = std::min(least, fast.active_contacts());
    wall_max = std::max(wall_max, fast.wall_contacts());
  }
  EXPECT_GT(most, 54);           // the projectile touched the block (54 lattice contacts before)
  EXPECT_LT(least, most);        // and contacts broke afterwards
  EXPECT_GT(wall_max, 0);        // the block was pushed onto the wall
  EXPECT_TRUE(control_left);     // the control left the tolerance
  omp_set_num_threads(saved);
}

// The half-kick factors (dt/2)/m and (dt/2)/I are computed once per particle (DemSystem::attach): a
// particle added later gets its own, and restore() recomputes them from the restored masses and dt.
// Both must continue bit for bit like a system that had the particles and dt from the start.
TEST(DemReferenceTwin, KickFactorsOfAddedAndRestoredParticles) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const Vec3 x_new{-3.0 * kTwinR, 0.3 * kTwinR, 0.2 * kTwinR}, v_new{2.0, 0.0, 0.0};
  Particles all = twin_block(3, 1e-3);
  all.add(x_new, kTwinR, 2.0 * kTwinRho, v_new);  // heavier than the block's spheres
  DemSystem whole(all, twin_params(true));
  DemSystem grown(twin_block(3, 1e-3), twin_params(true));
  grown.add_particle(x_new, kTwinR, 2.0 * kTwinRho, v_new, 0.0, 1.0);
  ASSERT_EQ(grown.dt(), whole.dt());  // the lighter block spheres set dt in both
  // A system of other masses and another dt, then given whole's state after 300 steps.
  Particles light = twin_block(3, 0.0);
  light.add(x_new, 0.5 * kTwinR, kTwinRho, {});
  auto prm = twin_params(true);
  prm.dt = 0.5 * whole.dt();
  DemSystem restored(light, prm);
  whole.run(300);
  grown.run(300);
  EXPECT_EQ(twin_differences(whole, grown), 0);
  restored.restore(whole.state());
  whole.run(700);
  grown.run(700);
  restored.run(700);
  EXPECT_EQ(twin_differences(whole, grown), 0);
  EXPECT_EQ(twin_differences(whole, restored), 0);
  EXPECT_LT(whole.particles().v.back().x, 1.5);  // the added sphere hit the block (launched at 2 m/s)
  omp_set_num_threads(saved);
}
