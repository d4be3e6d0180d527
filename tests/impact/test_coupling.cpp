// Electrostatics-DEM coupling (docs/model.md §B.3): the pair-corrected hold is exact for an isolated pair
// and keeps action-reaction; the coulomb fast path is exact for kappa_p = kappa_0; the break-up
// classification of hand-made states.
#include <gtest/gtest.h>


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
