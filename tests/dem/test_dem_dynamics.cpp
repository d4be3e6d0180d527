// Dynamic checks of the DEM (docs/model.md §A.4 items 5-7): undamped and damped sticking velocities of a
// head-on pair, the universality of g(e), a pair at rest staying at rest, conservation laws,
// break rules, thread-count independence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <omp.h>
#include <random>
#include <set>

#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/dem/contact/builtin_models.hpp"
#include "agglo/dem/dem_system.hpp"
#include "sticking.hpp"

using namespace agglo;
using namespace agglo::dem;
using namespace agglo::dem::testing;

namespace {

// Head-on collision of two equal spheres at relative speed v: true if they stay bonded.
bool sticks(const Sample& m, const DemParams& prm, double v) {
  Particles p;
  const double gap = 1e-3 * m.r;
  p.add({-(m.r + gap / 2), 0, 0}, m.r, m.rho, {v / 2, 0, 0});
  p.add({m.r + gap / 2, 0, 0}, m.r, m.rho, {-v / 2, 0, 0});
  DemSystem sys(p, prm);
  const double T0 = reference_period(sys.particles(), prm.contact);
  const long max_steps = static_cast<long>((gap / v + 40 * T0) / sys.dt());
  bool touched = false;
  for (long s = 0; s < max_steps; ++s) {
    sys.step();
    bool active = sys.active_contacts() > 0;
    if (active) touched = true;
    if (touched && !active) return false;  // contact broke: they separate
  }
  EXPECT_TRUE(touched);
  return true;
}

double sticking_velocity(const Sample& m, const DemParams& prm, double vlo, double vhi) {
  return bisect([&](double v) { return sticks(m, prm, v); }, vlo, vhi);
}

double reference_vs0(const Sample& m) {
  double R = m.r / 2, Estar = m.E / (2 * (1 - m.nu * m.nu));
  auto jkr = JkrPair::make(R, Estar, m.gamma);
  double mass = 4.0 / 3.0 * constants::pi * m.r * m.r * m.r * m.rho;
  return 1.3679 * std::sqrt(jkr.Fc * jkr.deltaC / (mass / 2));
}

TEST(DemDynamics, UndampedStickingVelocity) {
  Sample m;
  double vs0 = reference_vs0(m);
  double vs = sticking_velocity(m, params_for(m, 0.7, false), 0.5 * vs0, 2 * vs0);
  EXPECT_NEAR(vs / vs0, 1.0, 2e-3);
}

TEST(DemDynamics, DampedStickingRatioUniversal) {
  // g(e) = v_s / v_s0 (docs/model.md §A.4 item 6) for two very different materials.
  const std::pair<double, double> table[] = {{0.9, 1.275}, {0.7, 1.983}, {0.5, 3.123}, {0.3, 5.444}};
  Sample a;
  Sample b{2e-6, 1000, 5e9, 0.25, 0.05};
  for (auto [e, g] : table) {
    double ga = sticking_velocity(a, params_for(a, e, true), reference_vs0(a), 8 * reference_vs0(a)) / reference_vs0(a);
    double gb = sticking_velocity(b, params_for(b, e, true), reference_vs0(b), 8 * reference_vs0(b)) / reference_vs0(b);
    EXPECT_NEAR(ga, g, 5e-3 * g) << "e = " << e;
    EXPECT_NEAR(ga, gb, 2e-3 * g) << "e = " << e << " (universality)";
  }
}

TEST(DemDynamics, PairAtEquilibriumStaysAtRest) {
  Sample m;
  auto prm = params_for(m, 0.7, true);
  prm.contact.friction = 0.3;
  auto jkr = JkrPair::make(m.r / 2, m.E / (2 * (1 - m.nu * m.nu)), m.gamma);
  Particles p;
  double L = 2 * m.r - jkr.delta_equilibrium();
  p.add({-L / 2, 0, 0}, m.r, m.rho);
  p.add({L / 2, 0, 0}, m.r, m.rho);
  DemSystem sys(p, prm);
  sys.run(20000);
  EXPECT_EQ(sys.active_contacts(), 1);
  for (int k = 0; k < 2; ++k) {
    EXPECT_LT(norm(sys.particles().v[k]), 1e-12);
    EXPECT_LT(std::abs(sys.particles().x[k].x - (k ? L / 2 : -L / 2)), 1e-6 * jkr.deltaC);
  }
}

// Ruan & Li friction alone, or Marshall's sliding, rolling and twisting springs together.
impact::ImpactCase tetra_case(bool marshall) {
  impact::ImpactCase c;
  if (marshall) {
    c.dem.contact.models.tangential = contact::MarshallSliding::name;
    c.dem.contact.models.rolling = contact::MarshallRolling::name;
    c.dem.contact.models.twisting = contact::MarshallTwisting::name;
  }
  return c;
}

// Momentum and angular momentum are conserved to round-off in an isolated, violent run with
// friction and rotation (the projectile hits off-centre, so everything spins).
void check_conservation(bool marshall) {
  auto c = tetra_case(marshall);
  c.projectile.offset_radii = 0.7;
  auto p = impact::build_agglomerate(c);
  impact::add_projectile(p, c, 0.5);
  p.v[0] = {0.01, -0.02, 0.03};  // make the agglomerate move too
  DemSystem sys(p, c.dem);
  Vec3 P0 = sys.momentum(), L0 = sys.angular_momentum();
  double pscale = 5 * sys.particles().m[0] * 0.5;
  double lscale = pscale * 1e-4;
  bool spun = false;
  for (int s = 0; s < 40000; ++s) {
    sys.step();
    for (const auto& w : sys.particles().w) spun = spun || norm(w) > 1.0;
  }
  EXPECT_TRUE(spun);
  EXPECT_GT(sys.neighbors().builds(), 0);
  Vec3 dP = sys.momentum() - P0, dL = sys.angular_momentum() - L0;
  EXPECT_LT(norm(dP) / pscale, 1e-13);
  EXPECT_LT(norm(dL) / lscale, 1e-12);
}

TEST(DemDynamics, ConservationRuanLiFriction) { check_conservation(false); }
TEST(DemDynamics, ConservationMarshallFull) { check_conservation(true); }

TEST(DemDynamics, BreakRules) {
  // Pull a bonded pair apart slowly and record the overlap at which the contact breaks.
  for (auto rule : {BreakRule::marshall, BreakRule::lammps}) {
    Sample m;
    auto prm = params_for(m, 0.7, false);
    prm.contact.break_rule = rule;
    auto jkr = JkrPair::make(m.r / 2, m.E / (2 * (1 - m.nu * m.nu)), m.gamma);
    const ContactLaw law(prm.contact);
    ContactState s;
    PairKinematics k{{0, 0, 0}, {2 * m.r, 0, 0}, {}, {}, {}, {}, m.r, m.r, 1e-11, 1e-11};
    law.evaluate_pair(jkr, k, s, 1e-9);
    ASSERT_TRUE(s.active);
    double broke_at = 0.0;
    for (double d = 0.0; d > -2 * jkr.deltaC; d -= 1e-5 * jkr.deltaC) {
      k.xj = {2 * m.r - d, 0, 0};
      auto f = law.evaluate_pair(jkr, k, s, 1e-9);
      if (!s.active) {
        broke_at = d;
        break;
      }
      // While bonded the pair attracts with at most F_C.
      EXPECT_GE(f.f_on_i.x, 0.0);
      EXPECT_LE(f.f_on_i.x, jkr.Fc * (1 + 1e-9));
    }
    double expect = rule == BreakRule::marshall ? -1.0 : -0.48075;
    EXPECT_NEAR(broke_at / jkr.deltaC, expect, 2e-5);
    // No re-forming until delta >= 0 again.
    k.xj = {2 * m.r + 0.1 * jkr.deltaC, 0, 0};
    law.evaluate_pair(jkr, k, s, 1e-9);
    EXPECT_FALSE(s.active);
  }
}

// n spheres of radii 5-15 um at random in the box [0, box]^3.
void random_cloud(int n, unsigned seed, const Vec3& box, std::vector<Vec3>& x, std::vector<double>& r) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < n; ++k) {
    x.push_back({u(rng) * box.x, u(rng) * box.y, u(rng) * box.z});
    r.push_back(5e-6 + 10e-6 * u(rng));
  }
}

// Boxes that stress the sparse grid's row cursors: a flat slab, one cell, lines along x and z (the rows of
// one cell's neighbourhood adjacent or coinciding in key), and a dense cloud with far-flung particles.
TEST(DemDynamics, NeighborListMatchesBruteForce) {
  struct Cloud {
    int n;
    Vec3 box;
  };
  for (const Cloud& cloud : {Cloud{1500, {4e-4, 4e-4, 1e-4}}, Cloud{60, {1e-5, 1e-5, 1e-5}},
                             Cloud{400, {2e-3, 4e-5, 4e-5}}, Cloud{400, {4e-5, 4e-5, 2e-3}},
                             Cloud{400, {1.5e-4, 1.5e-4, 1.5e-4}}}) {
    std::vector<Vec3> x;
    std::vector<double> r;
    random_cloud(cloud.n, 7, cloud.box, x, r);
    if (cloud.n == 400 && cloud.box.x == cloud.box.z)  // far-flung outliers
      for (int k = 0; k < 6; ++k) x[static_cast<std::size_t>(k)] = Vec3{-1e-2, 5e-3, 2e-2} * double(k % 3 + 1);
    const double skin = 2e-6;
    NeighborList nl;
    nl.build(x, r, skin, [](Pair&) {});
    std::set<std::pair<unsigned, unsigned>> fast, slow;
    for (const auto& p : nl.pairs()) fast.insert({p.i, p.j});
    for (unsigned i = 0; i < x.size(); ++i)
      for (unsigned j = i + 1; j < x.size(); ++j)
        if (norm(x[j] - x[i]) < r[i] + r[j] + skin) slow.insert({i, j});
    EXPECT_GT(slow.size(), 100u) << cloud.n;
    EXPECT_EQ(fast.size(), nl.pairs().size()) << "repeated pairs, " << cloud.n;
    EXPECT_EQ(fast, slow) << cloud.n;
  }
}

// The list is sorted by (i, j) without repeats (the state merge of a rebuild and the pair loops rely on it),
// and a rebuild keeps an active contact whose spheres moved out of range, in its sorted place, with its state.
TEST(DemDynamics, NeighborListIsSortedAndKeepsBondedPairs) {
  std::vector<Vec3> x;
  std::vector<double> r;
  random_cloud(800, 11, {2e-4, 2e-4, 2e-4}, x, r);
  const double skin = 2e-6;
  NeighborList nl;
  nl.build(x, r, skin, [](Pair&) {});
  auto sorted_unique = [&] {
    const auto& ps = nl.pairs();
    for (std::size_t k = 1; k < ps.size(); ++k)
      if (!(std::make_pair(ps[k - 1].i, ps[k - 1].j) < std::make_pair(ps[k].i, ps[k].j))) return false;
    return true;
  };
  ASSERT_GT(nl.pairs().size(), 100u);
  EXPECT_TRUE(sorted_unique());
  // Bond a listed pair, then move its j far away: the rebuild keeps it (with its state), others as found.
  Pair& bonded = nl.pairs()[nl.pairs().size() / 2];
  bonded.state.active = true;
  bonded.state.a = 1.25e-7;
  const std::uint32_t i = bonded.i, j = bonded.j;
  x[j] = Vec3{1.0, 1.0, 1.0};
  nl.build(x, r, skin, [](Pair&) {});
  EXPECT_TRUE(sorted_unique());
  auto count_bonded = [&] {
    int found = 0;
    for (const auto& p : nl.pairs()) {
      if (p.i == i && p.j == j) {
        ++found;
        EXPECT_TRUE(p.state.active);
        EXPECT_EQ(p.state.a, 1.25e-7);
      } else {
        EXPECT_TRUE(p.i != j && p.j != j) << "the moved sphere has no other partner";
      }
    }
    return found;
  };
  EXPECT_EQ(count_bonded(), 1);
  // A list restored out of order (not what a checkpoint holds, but what a damaged one could) is sorted by the
  // next build, with the bonded pair still there once.
  NeighborState s = nl.state();
  std::reverse(s.pairs.begin(), s.pairs.end());
  nl.restore(s, x.size());
  nl.build(x, r, skin, [](Pair&) {});
  EXPECT_TRUE(sorted_unique());
  EXPECT_EQ(count_bonded(), 1);
}

TEST(DemDynamics, ThreadCountIndependent) {
  // A packed block of 8000 particles (> 4096 pairs: parallel force loop) gives identical states.
  auto make = [] {
    Particles p;
    Sample m;
    auto jkr = JkrPair::make(m.r / 2, m.E / (2 * (1 - m.nu * m.nu)), m.gamma);
    double L = 2 * m.r - jkr.delta_equilibrium();
    std::mt19937_64 rng(3);
    std::normal_distribution<double> nd(0, 0.01);
    for (int a = 0; a < 20; ++a)
      for (int b = 0; b < 20; ++b)
        for (int c = 0; c < 20; ++c) p.add({a * L, b * L, c * L}, m.r, m.rho, {nd(rng), nd(rng), nd(rng)});
    return p;
  };
  auto prm = params_for(Sample{}, 0.7, true);
  prm.contact.friction = 0.3;
  int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  DemSystem a(make(), prm);
  a.run(200);
  omp_set_num_threads(2);
  DemSystem b(make(), prm);
  b.run(200);
  omp_set_num_threads(saved);
  ASSERT_GT(a.active_contacts(), 10000);
  for (std::size_t k = 0; k < a.particles().size(); ++k) {
    ASSERT_EQ(a.particles().x[k].x, b.particles().x[k].x);
    ASSERT_EQ(a.particles().v[k].y, b.particles().v[k].y);
    ASSERT_EQ(a.particles().w[k].z, b.particles().w[k].z);
  }
}

}  // namespace
