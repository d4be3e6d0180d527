// Electrostatics-DEM coupling (docs/model.md §B.3): the pair-corrected hold is exact for an isolated pair
// and keeps action-reaction; the coulomb fast path is exact for kappa_p = kappa_0; the break-up
// classification of hand-made states.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>


#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"
#include "agglo/impact/experiment.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

ImpactCase charged_case(double kappa) {
  ImpactCase c;
  c.agglomerate.charged = true;
  c.agglomerate.permittivity = kappa;
  c.electrostatics = true;
  c.coupling.es.options.solver = "spectral";
  c.coupling.es.options.target_accuracy = 1e-4;
  return c;
}

dem::Particles state(const ImpactCase& c) {
  auto p = build_agglomerate(c);
  add_projectile(p, c, 0.2);
  // Put the projectile in contact with the edge it faces (near-contact gaps everywhere).
  p.x[4].x = p.x[0].x - 2.0 * p.r[0] + 2e-9;
  return p;
}

std::vector<Vec3> fresh_forces(const ImpactCase& c, const dem::Particles& p) {
  ElectrostaticForce f(c.coupling);
  std::vector<Vec3> F(p.size()), T(p.size());
  f.add_forces(p, 0, 0.0, F, T);
  return F;
}

TEST(Coupling, PairCorrectedHoldIsExactForAPairAndConservesMomentum) {
  for (double kappa : {2.5, 15.0}) {
    auto c = charged_case(kappa);
    c.coupling.es.update_fraction = 1.0;  // never re-solve during the comparison
    c.coupling.es.hold = "pair_corrected";
    c.coupling.es.options.target_accuracy = 1e-6;
    dem::Particles p;
    const double r = 10e-6, q = 1e-5 * 4 * constants::pi * r * r;
    p.add({0, 0, 0}, r, 2500, {}, q, kappa);
    p.add({2 * r - 4e-9, 0, 0}, r, 2500, {}, -q, kappa);
    ElectrostaticForce held(c.coupling);
    std::vector<Vec3> F(2), T(2);
    held.add_forces(p, 0, 0.0, F, T);
    for (double dx : {5e-9, 20e-9, -30e-9, 2e-6}) {
      auto moved = p;
      moved.x[1] += Vec3{dx, 0.3 * dx, 0};
      std::vector<Vec3> Fh(2), Th(2);
      held.add_forces(moved, 1, 0.0, Fh, Th);
      ASSERT_EQ(held.solves(), 1);
      auto exact = fresh_forces(c, moved);
      EXPECT_LT(norm(Fh[1] - exact[1]), 2e-3 * norm(exact[1])) << "kappa " << kappa << " dx " << dx;
      EXPECT_LT(norm(Fh[0] + Fh[1]), 1e-9 * norm(exact[1]));
    }
  }
}

// Error-controlled re-solves (electrostatics.force_tolerance) along a recorded trajectory: the charged
// kappa_p = 15 tetrahedron with the projectile 2 nm off an edge, every particle oscillating by 5 nm (a
// twentieth of the electrostatic gap) with its own direction and phase over 400 steps. Reference: a
// solve at every step. e(s) = max_k |F_k - F_ref,k| / max_k |F_ref,k|.
struct Trajectory {
  std::vector<dem::Particles> states;
  std::vector<std::vector<Vec3>> forces;  // solved at every step
};

Trajectory trajectory(const ImpactCase& c) {
  auto every = c;
  every.coupling.es.update_interval = 1;
  const auto p0 = state(c);
  ElectrostaticForce ref(every.coupling);
  Trajectory t;
  for (int s = 0; s < 400; ++s) {
    auto p = p0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      const double a = 1.7 * double(k) + 0.3;
      const Vec3 dir{std::cos(a) * std::sin(a + 1), std::sin(a) * std::sin(a + 1), std::cos(a + 1)};
      p.x[k] += dir * (5e-9 * std::sin(2 * constants::pi * s / 400.0 + a));
    }
    std::vector<Vec3> F(p.size()), T(p.size());
    ref.add_forces(p, s, 0.0, F, T);
    t.states.push_back(p);
    t.forces.push_back(F);
  }
  return t;
}

struct TrajectoryErrors {
  double max = 0.0, mean = 0.0;
  long solves = 0;
  HoldErrorStats measured;
};

// Errors from step `from` on (the steps before still run).
TrajectoryErrors errors_along(const Trajectory& t, const ImpactCase& c, std::size_t from = 0) {
  ElectrostaticForce held(c.coupling);
  TrajectoryErrors out;
  const std::size_t steps = t.states.size();
  for (std::size_t s = 0; s < steps; ++s) {
    const auto& p = t.states[s];
    std::vector<Vec3> F(p.size()), T(p.size());
    held.add_forces(p, static_cast<long>(s), 0.0, F, T);
    if (s < from) continue;
    double fmax = 0.0, emax = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      fmax = std::max(fmax, norm(t.forces[s][k]));
      emax = std::max(emax, norm(F[k] - t.forces[s][k]));
    }
    out.max = std::max(out.max, emax / fmax);
    out.mean += emax / fmax / double(steps - from);
  }
  out.solves = held.solves();
  out.measured = held.hold_error();
  return out;
}

// The controller aims at 0.5 tol from the errors measured at the solves; it cannot see an error that
// peaks inside an interval and falls again (motion turning back) or jumps faster than the motion, so
// the bound is empirical: at most 2 tol along this trajectory (measured 1.65 tol at 1e-2 and 0.79 tol at
// 1e-3; with an aim of 0.8 tol it was 1.9 and 1.56 tol), the mean below tol, with far fewer solves
// than steps; the errors measured at the solves are the trajectory's (within 1.5x of its maximum).
// The extrapolated hold (below) has its threshold rescaled by the square root of aim / error, as its
// error grows as the motion squared; at 1e-2 the intervals of both holds reach a quarter of the
// trajectory's period (the threshold grows 1.5x per solve from 1e-4 of the gap), where extrapolating a
// turning motion overshoots: measured 1.18 tol (2.17 tol before the extrapolation was limited to the
// span of its line, w <= 1); at 1e-3 1.09 tol with 35 solves instead of 98.
// Negative control: a threshold that never re-solves here exceeds the bound.
TEST(Coupling, ErrorControlledResolvesKeepTheHeldForceErrorNearTheTolerance) {
  auto c = charged_case(15.0);
  c.coupling.es.options.target_accuracy = 1e-3;
  const Trajectory t = trajectory(c);
  for (double tol : {1e-2, 1e-3}) {
    auto a = c;
    a.coupling.es.force_tolerance = tol;
    const auto e = errors_along(t, a);
    std::printf("tolerance %.0e: max %.3g, mean %.3g, %ld solves in 400 steps; at the solves max %.3g\n", tol, e.max,
                e.mean, e.solves, e.measured.max);
    EXPECT_LE(e.max, 2.0 * tol);
    EXPECT_LE(e.mean, tol);
    EXPECT_LE(e.solves, 100);
    EXPECT_EQ(e.measured.measured, e.solves - 1);
    EXPECT_LE(e.max, 1.5 * e.measured.max);
    // The extrapolated hold keeps these bounds with fewer solves.
    a.coupling.es.hold = "extrapolated";
    const auto x = errors_along(t, a);
    std::printf("  extrapolated hold: max %.3g, mean %.3g, %ld solves\n", x.max, x.mean, x.solves);
    EXPECT_LE(x.max, 2.0 * tol);
    EXPECT_LE(x.mean, tol);
    EXPECT_LE(x.solves, e.solves);
    if (tol < 5e-3) {  // at 1e-2 both are held back by the growth limit
      EXPECT_LT(2 * x.solves, e.solves);
    }
    EXPECT_EQ(x.measured.measured, x.solves - 1);
  }
  auto fixed = c;
  fixed.coupling.es.update_fraction = 0.025;  // the seed cases' fixed rule, for the record
  const auto f = errors_along(t, fixed);
  std::printf("fixed update_fraction 0.025: max %.3g, mean %.3g, %ld solves\n", f.max, f.mean, f.solves);
  auto never = c;
  never.coupling.es.update_fraction = 1.0;
  const auto n = errors_along(t, never);
  std::printf("no re-solve: max %.3g, mean %.3g\n", n.max, n.mean);
  EXPECT_EQ(n.solves, 1);
  EXPECT_GT(n.max, 2.0 * 1e-3) << "negative control: holding the first solution throughout";
}

// The extrapolated hold (hold = "extrapolated"): between solves the forces continue the straight line
// through the last two solutions, F(s) = F_1 + (s - s_1) / (s_1 - s_0) (F_1 - F_0), so its error along a
// smooth trajectory falls as the square of the interval where the constant hold's falls as the interval.
// Fixed intervals of 10 and 20 steps on the recorded trajectory: the extrapolated error falls by more than
// 3x when the interval halves, the constant one (negative control: a first-order hold) by less than 2.6x.
TEST(Coupling, ExtrapolatedHoldIsSecondOrderInTheInterval) {
  auto c = charged_case(15.0);
  c.coupling.es.options.target_accuracy = 1e-5;
  const Trajectory t = trajectory(c);
  auto at = [&](const char* hold, int interval) {
    auto a = c;
    a.coupling.es.hold = hold;
    a.coupling.es.update_fraction = 1.0;  // only the interval re-solves
    a.coupling.es.update_interval = interval;
    return errors_along(t, a, 40);  // after the first two intervals (the first has no line yet)
  };
  const auto c20 = at("constant", 20), c10 = at("constant", 10);
  const auto x20 = at("extrapolated", 20), x10 = at("extrapolated", 10);
  std::printf("constant: max %.3g (20 steps), %.3g (10); extrapolated: %.3g, %.3g\n", c20.max, c10.max, x20.max,
              x10.max);
  EXPECT_EQ(x20.solves, c20.solves);
  EXPECT_GT(x20.max / x10.max, 3.0);
  EXPECT_LT(c20.max / c10.max, 2.6);
  EXPECT_LT(x20.max, 0.5 * c20.max);
}

TEST(Coupling, CoulombFastPathIsExactForUnitPermittivity) {
  auto c = charged_case(1.0);
  auto p = state(c);
  ElectrostaticForce f(c.coupling);
  std::vector<Vec3> F(p.size()), T(p.size());
  f.add_forces(p, 0, 0.0, F, T);
  EXPECT_TRUE(f.used_fast_path());
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec3 ref;
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i) continue;
      Vec3 d = p.x[i] - p.x[j];
      ref += p.q[i] * p.q[j] / (4 * constants::pi * constants::eps0 * norm2(d)) * (d / norm(d));
    }
    EXPECT_LT(norm(F[i] - ref), 1e-12 * (norm(ref) + 1e-20));
  }
}

TEST(Coupling, ClassificationOfHandMadeStates) {
  // Two bonded particles plus one flying away from them: broken; the same one flying back: undecided.
  ImpactCase c;
  dem::Particles p;
  auto jkr = dem::JkrPair::make(5e-6, c.dem.contact.estar(), c.dem.contact.surface_energy);
  double L = 2e-5 - jkr.delta_equilibrium();
  p.add({0, 0, 0}, 1e-5, 2500);
  p.add({L, 0, 0}, 1e-5, 2500);
  p.add({-5e-5, 0, 0}, 1e-5, 2500, {-0.1, 0, 0});
  p.add({-9e-5, 0, 0}, 1e-5, 2500);  // "projectile", alone
  for (double vx : {-0.1, 0.1}) {
    auto q = p;
    q.v[2] = {vx, 0, 0};
    dem::DemSystem sys(q, c.dem);
    sys.step();
    auto out = classify(sys, 3, 1.0);
    ASSERT_EQ(out.fragments.size(), 1u);
    EXPECT_EQ(out.fragments[0].members, std::vector<int>{2});
    EXPECT_EQ(out.broken, vx < 0);
    EXPECT_EQ(out.undecided, vx > 0);
  }
}

}  // namespace
