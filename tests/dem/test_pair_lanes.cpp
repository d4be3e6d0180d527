// The fast pair loop's lanes (dem/contact/lanes.hpp, pair_kernel.hpp; docs/benchmarks_dem.md §9, §12): the
// one-thread loop evaluates the engaged pairs of a chunk four at a time (eight in its wide form, where the
// CPU has AVX-512); the parallel path's crossing pairs run the same law one pair at a time. Both must give
// the same bits, for every supported model set, in both forms, with mixed material pairs inside a group,
// fresh, held, breaking and beyond-the-table contacts.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "agglo/dem/contact/builtin_models.hpp"
#include "agglo/dem/contact/lanes.hpp"
#include "agglo/dem/contact/pair_blocks.hpp"
#include "agglo/dem/contact_law.hpp"
#include "agglo/dem/material.hpp"
#include "agglo/dem/neighbor_list.hpp"

namespace agglo::dem {
namespace {

constexpr double kR = 10e-6, kRho = 2500.0, kDt = 2e-9;

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

// Two materials (kinds 0..3) with different stiffness, adhesion, restitution and friction.
MaterialPairs two_materials() {
  ContactParams a, b, ab;
  b.youngs_modulus = 3e9, b.surface_energy = 0.05, b.restitution = 0.4, b.friction = 0.6;
  ab.pair_estar = 0.5 * (a.estar() + b.estar()), ab.pair_gstar = 0.5 * (a.gstar() + b.gstar());
  ab.surface_energy = 0.02, ab.restitution = 0.55, ab.friction = 0.45;
  MaterialPairs m;
  m.count = 2;
  m.table = {a, ab, ab, b};
  return m;
}

// n pairs (i, i + 1) of 2n spheres: gaps from -0.1 r (deep, beyond the JKR table) to beyond the break
// separation, random velocities and spins, a random sliding spring on the active ones.
struct PairSet {
  Particles p;
  std::vector<Pair> pairs;
};

PairSet random_pairs(int n, const MaterialPairs& mats, unsigned seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PairSet s;
  for (int k = 0; k < n; ++k) {
    const double r1 = kR * (1.0 + 0.5 * u(gen)), r2 = kR * (1.0 + 0.5 * u(gen));
    // runs of 24 pairs of one kind (whole groups of four and of eight), then 8 of random kinds (mixed groups)
    const bool run = k % 32 < 24;
    const std::uint32_t m1 = run ? (k / 32) % 2 : gen() % 2, m2 = run ? m1 : gen() % 2;
    const Vec3 dir{u(gen), u(gen), 1.5};
    const Vec3 n_hat = dir / norm(dir);
    const double gap = (k % 9 == 0) ? -0.1 * kR : 2e-3 * kR * u(gen);  // deep overlaps: beyond the table
    const Vec3 x1{1e-3 * k, 0.0, 0.0};
    s.p.add(x1, r1, kRho, Vec3{u(gen), u(gen), u(gen)} * 0.01, 0.0, 1.0, m1);
    s.p.add(x1 + (r1 + r2 + gap) * n_hat, r2, kRho, Vec3{u(gen), u(gen), u(gen)} * 0.01, 0.0, 1.0, m2);
    for (std::size_t q = s.p.size() - 2; q < s.p.size(); ++q) s.p.w[q] = Vec3{u(gen), u(gen), u(gen)} * 1e3;
    Pair pr;
    pr.i = static_cast<std::uint32_t>(2 * k), pr.j = pr.i + 1;
    pr.kind = mats.kind(m1, m2);
    const ContactParams& c = mats.table[pr.kind];
    pr.jkr = JkrPair::make(r1 * r2 / (r1 + r2), c.estar(), c.surface_energy);
    pr.state.active = gen() % 4 != 0;  // some fresh contacts, some held ones (which may break)
    if (pr.state.active) {
      pr.state.xi_t = Vec3{u(gen), u(gen), u(gen)} * 1e-9;
      pr.state.xi_r = Vec3{u(gen), u(gen), u(gen)} * 1e-9;
      pr.state.xi_q = 1e-3 * u(gen);
    }
    s.pairs.push_back(pr);
  }
  return s;
}

// The particles' forces and torques of s: per-pair forces `one` added in pair order (from zero).
void add_in_pair_order(PairSet& s, const std::vector<PairForce>& one) {
  for (auto& f : s.p.f) f = Vec3{};
  for (auto& t : s.p.t) t = Vec3{};
  for (std::size_t k = 0; k < s.pairs.size(); ++k) {
    const Pair& pr = s.pairs[k];
    s.p.f[pr.i] += one[k].f_on_i;
    s.p.t[pr.i] += one[k].t_on_i;
    s.p.f[pr.j] -= one[k].f_on_i;
    s.p.t[pr.j] += one[k].t_on_j;
  }
}

// Forces and torques of `start` from one pair at a time by the fast path's law (ContactLaw::fast_pair), with
// the pair states it leaves.
PairSet one_pair_at_a_time(const ContactLaw& law, const PairSet& start) {
  PairSet b = start;
  std::vector<PairForce> one;
  for (Pair& pr : b.pairs) {
    const Particles& q = b.p;
    const PairKinematics kin{q.x[pr.i], q.x[pr.j], q.v[pr.i], q.v[pr.j], q.w[pr.i],
                             q.w[pr.j], q.r[pr.i], q.r[pr.j], q.m[pr.i], q.m[pr.j]};
    one.push_back(law.fast_pair(pr.jkr, kin, pr.state, kDt, pr.kind));
  }
  add_in_pair_order(b, one);
  return b;
}

// The same from the parallel path's phase 1 (crossing_forces with every pair crossing, in `parts` parts).
PairSet all_crossing(const ContactLaw& law, const PairSet& start, std::size_t parts) {
  PairSet c = start;
  contact::PairBlocks blocks;
  for (std::size_t k = 0; k < c.pairs.size(); ++k) blocks.crossing.push_back(k);
  std::vector<PairForce> one(c.pairs.size());
  for (std::size_t part = 0; part < parts; ++part) law.crossing_forces(c.pairs, c.p, kDt, blocks, part, parts, one);
  add_in_pair_order(c, one);
  return c;
}

// Particles' forces and torques and pair states that differ in any bit between a and b.
int differences(const PairSet& a, const PairSet& b) {
  int diff = 0;
  for (std::size_t q = 0; q < a.p.size(); ++q) diff += !same_bits(a.p.f[q], b.p.f[q]) + !same_bits(a.p.t[q], b.p.t[q]);
  for (std::size_t k = 0; k < a.pairs.size(); ++k) {
    const ContactState &sa = a.pairs[k].state, &sb = b.pairs[k].state;
    diff += sa.active != sb.active || std::memcmp(&sa.a, &sb.a, sizeof(double)) != 0 || !same_bits(sa.xi_t, sb.xi_t) ||
            !same_bits(sa.xi_r, sb.xi_r) || std::memcmp(&sa.xi_q, &sb.xi_q, sizeof(double)) != 0;
  }
  return diff;
}

// Forces, torques and pair states after one evaluation by the chunked lanes loop (accumulate_pairs) and by
// the parallel path's phase 1 (crossing_forces, in three parts) against one pair at a time: the number of
// differing bits patterns of both; *engaged: the contacts active after the evaluation.
int lane_differences(const ContactLaw& law, const PairSet& start, int* engaged) {
  PairSet a = start;
  law.accumulate_pairs(a.pairs, a.p, kDt);
  const PairSet b = one_pair_at_a_time(law, start);
  *engaged = 0;
  for (const Pair& pr : a.pairs) *engaged += pr.state.active;
  return differences(a, b) + differences(all_crossing(law, start, 3), b);
}

// Every combination of the built-in models (all have lane forms); Marshall's rolling and twisting springs
// only with its sliding spring (the registry's rule).
std::vector<contact::ModelNames> every_combination() {
  std::vector<contact::ModelNames> out;
  for (const char* t : {contact::RuanLiFriction::name, contact::MarshallSliding::name})
    for (const char* d : {contact::AlphaDamping::name, contact::NoDamping::name})
      for (const char* r : {contact::NoRolling::name, contact::MarshallRolling::name})
        for (const char* q : {contact::NoTwisting::name, contact::MarshallTwisting::name}) {
          const bool springs = std::string(r) != "none" || std::string(q) != "none";
          if (springs && std::string(t) != contact::MarshallSliding::name) continue;
          contact::ModelNames names;
          names.tangential = t, names.damping = d, names.rolling = r, names.twisting = q;
          out.push_back(names);
        }
  return out;
}

// Every model combination in one form of the loop: lanes::set_wide_lanes(wide) (the wide form only where the
// CPU has it; the other cases run the four-pair form twice).
void expect_lanes_equal_one_pair_at_a_time(bool wide) {
  contact::lanes::set_wide_lanes(wide);
  const MaterialPairs mats = two_materials();
  const auto combinations = every_combination();
  ASSERT_EQ(combinations.size(), 10u);
  for (const auto& names : combinations) {
    const ContactLaw law(mats, names);
    for (unsigned seed = 1; seed <= 4; ++seed) {
      const PairSet s = random_pairs(150, mats, seed);  // 150: chunks of 64 and a partial one
      int engaged = 0;
      EXPECT_EQ(lane_differences(law, s, &engaged), 0) << names.tangential << " " << names.damping << " "
                                                       << names.rolling << " " << names.twisting << " seed " << seed
                                                       << (contact::lanes::wide_lanes() ? " wide" : " four");
      EXPECT_GT(engaged, 60) << "the comparison needs engaged contacts";
    }
  }
  contact::lanes::set_wide_lanes(true);
}

TEST(PairLanes, LanesEqualOnePairAtATime) { expect_lanes_equal_one_pair_at_a_time(false); }

TEST(PairLanes, WideLanesEqualOnePairAtATime) {
  expect_lanes_equal_one_pair_at_a_time(true);
  if (!contact::lanes::wide_lanes()) GTEST_SKIP() << "this CPU has no AVX-512 (x86-64-v4): the wide form never runs";
}

// A 4 x 4 x 4 block of touching spheres (jittered), every pair within 2.2 r listed in the neighbour list's
// order (by i, then j): consecutive pairs share their i, and a particle is the j of earlier pairs and the i
// of later ones, which the sums of the pair loop keep in registers (PairKernel::RunningSum).
PairSet block_pairs(unsigned seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PairSet s;
  const double spacing = 2.0 * kR * (1.0 - 1e-3);
  for (int q = 0; q < 64; ++q) {
    const Vec3 x = Vec3{double(q % 4), double(q / 4 % 4), double(q / 16)} * spacing +
                   Vec3{u(gen), u(gen), u(gen)} * (2e-4 * kR);
    s.p.add(x, kR, kRho, Vec3{u(gen), u(gen), u(gen)} * 0.01, 0.0, 1.0, 0);
    s.p.w.back() = Vec3{u(gen), u(gen), u(gen)} * 1e3;
  }
  const ContactParams c;
  for (std::uint32_t i = 0; i < 64; ++i)
    for (std::uint32_t j = i + 1; j < 64; ++j) {
      if (norm(s.p.x[j] - s.p.x[i]) > 2.2 * kR) continue;
      Pair pr;
      pr.i = i, pr.j = j;
      pr.jkr = JkrPair::make(0.5 * kR, c.estar(), c.surface_energy);
      pr.state.active = gen() % 4 != 0;
      if (pr.state.active) pr.state.xi_t = Vec3{u(gen), u(gen), u(gen)} * 1e-9;
      s.pairs.push_back(pr);
    }
  return s;
}

TEST(PairLanes, SumsOfPairsSharingParticlesEqualOnePairAtATime) {
  contact::ModelNames names;
  names.tangential = contact::MarshallSliding::name;
  MaterialPairs one;
  one.table = {ContactParams{}};
  const ContactLaw law(one, names);
  for (bool wide : {false, true}) {
    contact::lanes::set_wide_lanes(wide);
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const PairSet s = block_pairs(seed);
      int shared = 0;  // pairs whose i is the previous pair's i (what the test is about)
      for (std::size_t k = 1; k < s.pairs.size(); ++k) shared += s.pairs[k].i == s.pairs[k - 1].i;
      ASSERT_GT(shared, 60);
      int engaged = 0;
      EXPECT_EQ(lane_differences(law, s, &engaged), 0) << "seed " << seed << (wide ? " wide" : " four");
      EXPECT_GT(engaged, 80);
    }
  }
  contact::lanes::set_wide_lanes(true);
}

// Negative control: the comparison sees a relative change of 1e-12 in one velocity of one engaged pair.
TEST(PairLanes, ComparisonSeesATinyChange) {
  const MaterialPairs mats = two_materials();
  contact::ModelNames names;
  names.tangential = contact::MarshallSliding::name;
  const ContactLaw law(mats, names);
  const PairSet s = random_pairs(150, mats, 3);
  PairSet a = s;
  law.accumulate_pairs(a.pairs, a.p, kDt);
  std::size_t k = 0;
  while (!a.pairs[k].state.active) ++k;
  PairSet t = s;
  t.p.v[t.pairs[k].j].x *= 1.0 + 1e-12;
  int engaged = 0;
  EXPECT_EQ(lane_differences(law, t, &engaged), 0);
  law.accumulate_pairs(t.pairs, t.p, kDt);
  EXPECT_FALSE(same_bits(a.p.f[a.pairs[k].i], t.p.f[a.pairs[k].i]));
}

}  // namespace
}  // namespace agglo::dem
