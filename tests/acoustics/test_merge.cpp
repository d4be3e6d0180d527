// Weighted coalescence rules (seed eqs. 15-21), conservation in coalescence (docs/model.md §C.7.4), hard-sphere
// rebound (eqs. 22-24), split-merge (eqs. 25-29) and the energy compensation of eq. 30.
#include <cmath>

#include <gtest/gtest.h>

#include "agglo/acoustics/merge.hpp"
#include "agglo/acoustics/outcomes.hpp"
#include "agglo/core/constants.hpp"

using namespace agglo::acoustics;
using agglo::Vec3;
using agglo::constants::pi;

namespace {
struct Pair {
  Gas gas = Gas::air(298.15, 101325.0, true);
  Sound snd = Sound::make(gas, true, 140.0, 2000.0);
  SampleSet p;
  // i: solid 1 um, j: droplet 10 um
  Pair(double wi, double wj) {
    const double vi = pi * 1e-18 / 6, vj = pi * 1e-15 / 6;
    p.add(0.001, 0.002, 0.003, vi, 0, 2500 * vi, wi, 0, gas, snd);
    p.add(0.0011, 0.002, 0.003, 0, vj, 1000 * vj, wj, 1, gas, snd);
    p.vx = {0.5, -0.1};
    p.vy = {0.0, 0.2};
    p.vz = {-0.01, -0.3};
  }
  double total(const std::vector<double>& q) const { return p.w[0] * q[0] + p.w[1] * q[1]; }
  Vec3 mom() const { return momentum(p); }
};
}  // namespace

TEST(WeightedCoalescence, EqualEvenWeightsHalveBoth) {
  Pair a(4, 4);
  const double vs = a.total(a.p.vol_s), vl = a.total(a.p.vol_l), m = a.total(a.p.mass);
  const Vec3 P = a.mom();
  const double ma = a.p.mass[0] + a.p.mass[1];
  const double vxa = (a.p.mass[0] * 0.5 + a.p.mass[1] * -0.1) / ma;
  coalesce_weighted(a.p, 0, 1, a.gas, a.snd);
  EXPECT_EQ(a.p.w[0], 2);
  EXPECT_EQ(a.p.w[1], 2);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(a.p.d[k], std::cbrt(1e-18 + 1e-15), 1e-20);  // eq. 15
    EXPECT_NEAR(a.p.rho[k], 6 * ma / (pi * (1e-18 + 1e-15)), 1e-9);  // eq. 16
    EXPECT_NEAR(a.p.vx[k], vxa, 1e-15);  // eq. 17
    EXPECT_EQ(a.p.phase(k), Phase::mixed);
  }
  // 4 real pairs -> 4 merged particles: totals unchanged.
  EXPECT_NEAR(a.total(a.p.vol_s) / vs, 1.0, 1e-15);
  EXPECT_NEAR(a.total(a.p.vol_l) / vl, 1.0, 1e-15);
  EXPECT_NEAR(a.total(a.p.mass) / m, 1.0, 1e-15);
  EXPECT_NEAR(norm(a.mom() - P), 0.0, 1e-15 * norm(P));
}

TEST(WeightedCoalescence, RulesConserveSolidLiquidMassAndMomentum) {
  // Real particles: w_i of i and w_j of j; after min(w_i, w_j) coalescences the totals are unchanged.
  for (auto [wi, wj] : {std::pair{4.0, 4.0}, {5.0, 5.0}, {7.0, 3.0}, {2.0, 9.0}, {1.0, 1.0}}) {
    Pair a(wi, wj);
    const double vs = a.total(a.p.vol_s), vl = a.total(a.p.vol_l), m = a.total(a.p.mass);
    const Vec3 P = a.mom();
    const double n_before = wi + wj;
    coalesce_weighted(a.p, 0, 1, a.gas, a.snd);
    EXPECT_NEAR(a.total(a.p.vol_s) / vs, 1.0, 1e-14) << wi << " " << wj;
    EXPECT_NEAR(a.total(a.p.vol_l) / vl, 1.0, 1e-14);
    EXPECT_NEAR(a.total(a.p.mass) / m, 1.0, 1e-14);
    const Vec3 Q = a.mom();
    EXPECT_NEAR(Q.x, P.x, 1e-14 * std::abs(P.x) + 1e-30);
    EXPECT_NEAR(Q.y, P.y, 1e-14 * std::abs(P.y) + 1e-30);
    EXPECT_NEAR(Q.z, P.z, 1e-14 * std::abs(P.z) + 1e-30);
    // Number of real particles drops by the number of real coalescences min(w_i, w_j).
    EXPECT_EQ(a.p.w[0] + a.p.w[1], n_before - std::min(wi, wj));
  }
}

TEST(WeightedCoalescence, OddAndUnequalWeightRules) {
  Pair odd(5, 5);  // eq. 19
  coalesce_weighted(odd.p, 0, 1, odd.gas, odd.snd);
  EXPECT_EQ(odd.p.w[0], 3);
  EXPECT_EQ(odd.p.w[1], 2);
  EXPECT_EQ(odd.p.d[0], odd.p.d[1]);
  Pair gt(7, 3);  // eq. 20: i keeps its state with 4, j merged with 3
  const double di = gt.p.d[0], vxi = gt.p.vx[0];
  coalesce_weighted(gt.p, 0, 1, gt.gas, gt.snd);
  EXPECT_EQ(gt.p.w[0], 4);
  EXPECT_EQ(gt.p.w[1], 3);
  EXPECT_EQ(gt.p.d[0], di);
  EXPECT_EQ(gt.p.vx[0], vxi);
  EXPECT_EQ(gt.p.phase(0), Phase::solid);
  EXPECT_EQ(gt.p.phase(1), Phase::mixed);
  Pair lt(2, 9);  // eq. 21: i merged with 2, j keeps its state with 7
  const double dj = lt.p.d[1];
  coalesce_weighted(lt.p, 0, 1, lt.gas, lt.snd);
  EXPECT_EQ(lt.p.w[0], 2);
  EXPECT_EQ(lt.p.w[1], 7);
  EXPECT_EQ(lt.p.d[1], dj);
  EXPECT_EQ(lt.p.phase(1), Phase::liquid);
  EXPECT_EQ(lt.p.phase(0), Phase::mixed);
  EXPECT_NEAR(lt.p.d[0], std::cbrt(1e-18 + 1e-15), 1e-20);
}

TEST(Rebound, HardSphereNormalRestitutionAndMomentum) {
  const Vec3 vi{1.0, 0.3, 0.0}, vj{-0.5, 0.0, 0.2};
  const Vec3 n = Vec3{1.0, 0.2, 0.1} / std::sqrt(1.05);
  Vec3 a, b;
  // Without friction: normal relative velocity reversed and scaled by e, tangential unchanged.
  hard_sphere_rebound(vi, vj, 2.0, 3.0, n, 0.6, 0.0, a, b);
  const Vec3 G = vi - vj, Gr = a - b;
  EXPECT_NEAR(dot(Gr, n), -0.6 * dot(G, n), 1e-14);
  EXPECT_NEAR(norm(Gr - dot(Gr, n) * n), norm(G - dot(G, n) * n), 1e-14);
  const Vec3 P = 2.0 * vi + 3.0 * vj, Q = 2.0 * a + 3.0 * b;
  EXPECT_NEAR(norm(P - Q), 0.0, 1e-14);
  // With friction: sliding (eq. 22) removes f (1+e) G.n of tangential velocity; sticking (eq. 23) 2/7 |G_t|.
  const double f = 0.2, e = 0.6, gn = dot(G, n), gt = norm(G - gn * n);
  hard_sphere_rebound(vi, vj, 2.0, 3.0, n, e, f, a, b);
  const Vec3 Gr2 = a - b;
  const double gt2 = norm(Gr2 - dot(Gr2, n) * n);
  if (gn / gt <= 2.0 / (7 * f * (1 + e)))
    EXPECT_NEAR(gt2, gt - f * (1 + e) * gn, 1e-12);
  else
    EXPECT_NEAR(gt2, 5.0 / 7.0 * gt, 1e-12);
  EXPECT_NEAR(norm(2.0 * vi + 3.0 * vj - (2.0 * a + 3.0 * b)), 0.0, 1e-14);
  // Head-on (no tangential part) takes the sticking branch: G_t stays 0.
  hard_sphere_rebound(Vec3{1, 0, 0}, Vec3{0, 0, 0}, 1, 1, Vec3{1, 0, 0}, e, f, a, b);
  EXPECT_NEAR(a.x, 0.5 * (1 - e), 1e-15);
  EXPECT_NEAR(b.x, 0.5 * (1 + e), 1e-15);
}

TEST(Rebound, WetRestitutionAndCriticalVelocities) {
  OutcomeParams o;
  const double di = 1e-6, dj = 20e-6;
  const double vw = critical_velocity_wet(o, di, dj);
  EXPECT_NEAR(vw, 9 * 8.9e-4 * 21e-6 / (8 * 2500 * 20e-12) * (1 + 1 / 0.6) * std::log(10.0), 1e-12);
  // e_wet = e (1 - v_cr,wet / |G.n|): zero at the critical velocity, -> e for fast impacts.
  EXPECT_NEAR(wet_restitution(o, di, dj, vw), 0.0, 1e-12);
  EXPECT_NEAR(wet_restitution(o, di, dj, 2 * vw), 0.3, 1e-12);
  const double vd = critical_velocity_dry(o, 0.2e-6, 0.4e-6, 2500, 2500);
  EXPECT_NEAR(vd, 1e-19 * 0.8 / (pi * 0.2e-6 * 16e-20 * 0.36 * std::sqrt(6 * 3e8 * 2500 * 1.5)), 1e-12);
}

TEST(SplitMerge, MomentumExactEnergyLossBookedAndCompensated) {
  Pair a(10, 3);
  const Vec3 n = Vec3{1.0, 0.5, -0.2} / std::sqrt(1.29);
  const Vec3 G{a.p.vx[0] - a.p.vx[1], a.p.vy[0] - a.p.vy[1], a.p.vz[0] - a.p.vz[1]};
  ASSERT_GT(dot(G, n), 0.0);
  const Vec3 P = momentum(a.p);
  const double E0 = kinetic_energy(a.p);
  // Elastic, frictionless: the real pairs keep their energy; only the merge of i* and i** loses some.
  Vec3 vir, vjr;
  hard_sphere_rebound(Vec3{a.p.vx[0], a.p.vy[0], a.p.vz[0]}, Vec3{a.p.vx[1], a.p.vy[1], a.p.vz[1]}, a.p.mass[0],
                      a.p.mass[1], n, 1.0, 0.0, vir, vjr);
  const Vec3 v0{a.p.vx[0], a.p.vy[0], a.p.vz[0]};
  const Vec3 vm = (3.0 * vir + 7.0 * v0) / 10.0;  // eq. 25
  const double dE_hand = 0.5 * a.p.mass[0] * (3 * norm2(vir) + 7 * norm2(v0)) - 0.5 * a.p.mass[0] * 10 * norm2(vm);
  const double dE = rebound_weighted(a.p, 0, 1, n, 1.0, 0.0);
  EXPECT_NEAR(dE, dE_hand, 1e-12 * dE_hand);
  EXPECT_GT(dE, 0.0);
  EXPECT_NEAR(a.p.vx[0], vm.x, 1e-15);
  EXPECT_NEAR(a.p.vx[1], vjr.x, 1e-15);
  const Vec3 Q = momentum(a.p);
  EXPECT_NEAR(norm(Q - P), 0.0, 1e-14 * norm(P));
  const double E1 = kinetic_energy(a.p);
  EXPECT_NEAR(E1 + dE, E0, 1e-12 * E0);  // bookkeeping: lost = eq. 29
  EXPECT_DOUBLE_EQ(a.p.debt[0], dE);
  EXPECT_DOUBLE_EQ(a.p.debt_ref[0], 10 * a.p.mass[0]);
  // Compensation: the debt given back to a pair restores the energy exactly, momentum unchanged.
  ASSERT_TRUE(add_relative_energy(a.p, 0, 1, dE));
  EXPECT_NEAR(kinetic_energy(a.p), E0, 1e-12 * E0);
  EXPECT_NEAR(norm(momentum(a.p) - P), 0.0, 1e-14 * norm(P));
}
