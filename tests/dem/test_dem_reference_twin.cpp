// The fast DEM pair step against its reference twin (DemSystem::set_reference_kernel; issue 27): on one
// thread the fast path adds every pair force straight into the particles, the reference evaluates into
// a per-pair buffer and gathers it per particle (today's kernel, also the parallel path). The sums run
// in the same order, so every position, velocity, force and contact state must be bit for bit equal:
// on an adhesive block at JKR equilibrium and on an impact that forms and breaks contacts, with a wall.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <omp.h>
#include <random>

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

// AGGLO_THREAD_PROBE=off for the guard's lifetime: DemSystem::step keeps the whole team at every step (no
// probes at one thread, core/thread_choice.hpp), so that a test of the parallel path runs it throughout.
struct FixedThreadCount {
  FixedThreadCount() { setenv("AGGLO_THREAD_PROBE", "off", 1); }
  ~FixedThreadCount() { unsetenv("AGGLO_THREAD_PROBE"); }
};

}  // namespace

TEST(DemReferenceTwin, BlockAtEquilibriumBitIdentical) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);  // the fast path runs on one thread
  for (bool all_models : {false, true}) {
    DemSystem fast(twin_block(5, 1e-3), twin_params(all_models));
    DemSystem ref(twin_block(5, 1e-3), twin_params(all_models));
    ref.set_reference_kernel(true);
    EXPECT_FALSE(fast.reference_kernel());
    for (int chunk = 0; chunk < 6; ++chunk) {
      fast.run(50);
      ref.run(50);
      ASSERT_EQ(twin_differences(fast, ref), 0) << "step " << fast.steps() << ", all models " << all_models;
    }
    EXPECT_EQ(fast.active_contacts(), 300);  // 3 * 5 * 5 * 4 lattice contacts, all kept
  }
  omp_set_num_threads(saved);
}

// The parallel fast path (blocks of pairs, contact/pair_blocks.hpp: more than one thread and more than
// kParallelThreshold pairs) against the reference twin on one thread: a 13^3 block (6084 lattice contacts),
// every particle moving, so that contacts also form and break; 2 and 3 threads (uneven blocks).
TEST(DemReferenceTwin, ParallelBlocksBitIdentical) {
  const FixedThreadCount fixed;
  const int saved = omp_get_max_threads();
  for (int threads : {2, 3}) {
    omp_set_num_threads(1);
    DemSystem ref(twin_block(13, 0.05), twin_params(true));
    ref.set_reference_kernel(true);
    ref.run(60);
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

// The neighbour list's rebuild test folded into the parallel drift loop (DemSystem::step, parallel_any)
// against the reference twin on one thread, which tests in needs_rebuild's serial pass (it fails when the
// folded test never asks for a rebuild: 1 build against 6): a 17^3 block
// (4913 particles, above kParallelThreshold: the drift loop runs on the team) fast enough that the list is
// rebuilt during the run (not vacuous: more builds than the first), 2 and 3 threads; the same rebuild steps
// and every bit of the state.
TEST(DemReferenceTwin, RebuildTestInTheParallelDriftBitIdentical) {
  const FixedThreadCount fixed;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  DemSystem ref(twin_block(17, 2.0), twin_params(true));
  ref.set_reference_kernel(true);
  ref.run(40);
  ASSERT_GT(ref.neighbors().builds(), 2);
  for (int threads : {2, 3}) {
    omp_set_num_threads(threads);
    DemSystem fast(twin_block(17, 2.0), twin_params(true));
    fast.run(40);
    ASSERT_TRUE(runs_parallel(static_cast<std::int64_t>(fast.particles().size())));
    EXPECT_EQ(fast.neighbors().builds(), ref.neighbors().builds()) << threads << " threads";
    EXPECT_EQ(twin_differences(fast, ref), 0) << threads << " threads";
  }
  omp_set_num_threads(saved);
}

// The parallel step with the forces it adds after its region (a wall and gravity: DemSystem::parallel_step's
// closing kick after the region) and the exact gas-drag kick: a 13^3 block (more than kParallelThreshold
// pairs) with its particles moving, dragged by a gas flow and pulled onto a wall it touches, on 2 and 3 threads against
// the reference twin on one thread, every bit (it fails when the wall forces are left out of the parallel step).
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
  omp_set_num_threads(1);
  DemSystem ref = make(true);
  ref.run(120);
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
// bit equals the reference twin's on one thread.
TEST(DemReferenceTwin, StepsOfBothThreadCountsBitIdentical) {
  const int saved = omp_get_max_threads();
  const long steps = 3 * static_cast<long>(ThreadChoice::kProbeSteps);
  omp_set_num_threads(1);
  DemSystem ref(twin_block(13, 0.05), twin_params(true));
  ref.set_reference_kernel(true);
  ref.run(steps);
  omp_set_num_threads(2);
  DemSystem fast(twin_block(13, 0.05), twin_params(true));
  fast.run(steps);
  omp_set_num_threads(saved);
  EXPECT_GE(fast.thread_choice().steps_at_one(), ThreadChoice::kProbeSteps);  // (the third kProbeSteps: either)
  EXPECT_GE(fast.thread_choice().steps_at_max(), ThreadChoice::kProbeSteps);
  EXPECT_EQ(fast.thread_choice().steps_at_max() + fast.thread_choice().steps_at_one(), static_cast<std::uint64_t>(steps));
  EXPECT_EQ(twin_differences(fast, ref), 0);
}

TEST(DemReferenceTwin, ImpactOnWallBitIdentical) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  auto make = [](bool reference) {
    Particles p = twin_block(3, 0.0);
    double xmax = 0.0;
    for (const auto& x : p.x) xmax = std::max(xmax, x.x);
    p.add(Vec3{-3.0 * kTwinR, 0.3 * kTwinR, 0.2 * kTwinR}, kTwinR, kTwinRho, Vec3{2.0, 0.0, 0.0});  // projectile
    auto prm = twin_params(true);
    prm.walls.push_back(Wall{Vec3{xmax + 1.2 * kTwinR, 0.0, 0.0}, Vec3{-1.0, 0.0, 0.0}});
    DemSystem sys(std::move(p), prm);
    sys.set_reference_kernel(reference);
    return sys;
  };
  DemSystem fast = make(false), ref = make(true);
  int most = 0, least = 1 << 30, wall_max = 0;
  for (int s = 1; s <= 2000; ++s) {
    fast.step();
    ref.step();
    if (s % 100 == 0) {
      ASSERT_EQ(twin_differences(fast, ref), 0) << "step " << s;
    }
    most = std::max(most, fast.active_contacts());
    if (most > 54) least = std::min(least, fast.active_contacts());
    wall_max = std::max(wall_max, fast.wall_contacts());
  }
  EXPECT_GT(most, 54);           // the projectile touched the block (54 lattice contacts before)
  EXPECT_LT(least, most);        // and contacts broke afterwards
  EXPECT_GT(wall_max, 0);        // the block was pushed onto the wall
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
