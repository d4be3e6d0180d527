// Materials per particle (dem/material.hpp, docs/model.md §A.2 "Materials"): the pair rules and their
// symmetry, the pull-off force and the undamped sticking velocity of a pair of two different materials
// and radii against the closed forms F_C = 3/2 pi w R* (w = 2 sqrt(gamma_a gamma_b)) and
// v_s = 1.3679 sqrt(F_C delta_C / m*), a sphere against a wall of another material, and a named
// material with the default's values reproducing the single-material run bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sticking.hpp"

using namespace agglo;
using namespace agglo::dem;
using namespace agglo::dem::testing;

namespace {

// Silica-like (default, id 0) and a softer, more adhesive, more slippery material (id 1).
DemParams two_materials(bool damping) {
  DemParams prm = params_for(Sample{}, 0.7, damping);
  prm.contact.friction = 0.3;
  Material soft;
  soft.name = "soft";
  soft.density = 1200.0;
  soft.youngs_modulus = 0.2e9;
  soft.poisson_ratio = 0.45;
  soft.surface_energy = 0.04;
  soft.restitution = 0.5;
  soft.friction = 0.1;
  prm.materials = {soft};
  return prm;
}

const double kR0 = 10e-6, kR1 = 6e-6;  // radii of the two spheres [m]

// Closed-form JKR constants of the mixed pair by the rules of material.hpp.
JkrPair mixed_closed_form(const DemParams& prm) {
  const auto& a = prm.contact;
  const auto& b = prm.materials[0];
  const double estar = 1.0 / ((1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                              (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
  return JkrPair::make(kR0 * kR1 / (kR0 + kR1), estar, std::sqrt(a.surface_energy * b.surface_energy));
}

double mass(double r, double rho) { return 4.0 / 3.0 * constants::pi * r * r * r * rho; }

// Sphere 0 (material 0, radius kR0) and sphere 1 (material 1, radius kR1) head-on at relative speed v,
// total momentum zero: true if they stay bonded for 40 contact periods.
bool mixed_pair_sticks(const DemParams& prm, double v) {
  const double m0 = mass(kR0, 2500.0), m1 = mass(kR1, prm.materials[0].density);
  const double gap = 1e-3 * kR1;
  Particles p;
  p.add({-(kR0 + gap / 2), 0, 0}, kR0, 2500.0, {v * m1 / (m0 + m1), 0, 0});
  p.add({kR1 + gap / 2, 0, 0}, kR1, prm.materials[0].density, {-v * m0 / (m0 + m1), 0, 0}, 0.0, 1.0, 1);
  DemSystem sys(p, prm);
  const long max_steps = static_cast<long>((gap / v + 40 * reference_period(sys.particles(), prm)) / sys.dt());
  bool touched = false;
  for (long s = 0; s < max_steps; ++s) {
    sys.step();
    const bool active = sys.active_contacts() > 0;
    touched = touched || active;
    if (touched && !active) return false;
  }
  EXPECT_TRUE(touched);
  return true;
}

}  // namespace

TEST(Materials, PairRules) {
  const DemParams prm = two_materials(true);
  const MaterialPairs mats(prm.contact, prm.materials);
  ASSERT_EQ(mats.count, 2u);
  const auto& a = prm.contact;
  const auto& b = prm.materials[0];
  const ContactParams& ab = mats.at(0, 1);
  EXPECT_DOUBLE_EQ(1.0 / ab.estar(), (1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                                         (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
  const double ga = a.youngs_modulus / (2 * (1 + a.poisson_ratio)), gb = b.youngs_modulus / (2 * (1 + b.poisson_ratio));
  EXPECT_DOUBLE_EQ(1.0 / ab.gstar(), (2 - a.poisson_ratio) / ga + (2 - b.poisson_ratio) / gb);
  EXPECT_DOUBLE_EQ(ab.surface_energy, std::sqrt(0.01 * 0.04));
  EXPECT_DOUBLE_EQ(ab.restitution, std::sqrt(0.7 * 0.5));
  EXPECT_EQ(ab.friction, 0.1);
  // One material: its own values, exactly those of a single-material case.
  EXPECT_EQ(mats.at(0, 0).estar(), prm.contact.estar());
  EXPECT_EQ(mats.at(0, 0).gstar(), prm.contact.gstar());
  EXPECT_EQ(mats.at(1, 1).estar(), b.youngs_modulus / (2 * (1 - b.poisson_ratio * b.poisson_ratio)));
  EXPECT_EQ(mats.at(1, 1).surface_energy, b.surface_energy);
}

TEST(Materials, PairValuesAreSymmetric) {
  const DemParams prm = two_materials(true);
  const MaterialPairs mats(prm.contact, prm.materials);
  const ContactParams &ab = mats.at(0, 1), &ba = mats.at(1, 0);
  EXPECT_EQ(ab.estar(), ba.estar());
  EXPECT_EQ(ab.gstar(), ba.gstar());
  EXPECT_EQ(ab.surface_energy, ba.surface_energy);
  EXPECT_EQ(ab.restitution, ba.restitution);
  EXPECT_EQ(ab.friction, ba.friction);
  // The pair in either order follows the same trajectory (to round-off: the levers are computed from
  // the other end).
  const double m0 = mass(kR0, 2500.0), m1 = mass(kR1, 1200.0);
  Particles p;
  p.add({0, 0, 0}, kR0, 2500.0, {0.01, 0.002, 0}, 0.0, 1.0, 0);
  p.add({kR0 + kR1 - 1e-9, 1e-8, 0}, kR1, 1200.0, {-0.01, 0, 0.001}, 0.0, 1.0, 1);
  Particles q;  // the same two in the other order
  q.add(p.x[1], kR1, 1200.0, p.v[1], 0.0, 1.0, 1);
  q.add(p.x[0], kR0, 2500.0, p.v[0], 0.0, 1.0, 0);
  DemSystem sp(p, prm), sq(q, prm);
  EXPECT_EQ(sp.dt(), sq.dt());
  for (int s = 0; s < 200; ++s) {
    sp.step();
    sq.step();
  }
  ASSERT_EQ(sp.active_contacts(), 1);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(sp.particles().x[0][c], sq.particles().x[1][c], 1e-12 * kR0);
    EXPECT_NEAR(sp.particles().v[1][c], sq.particles().v[0][c], 1e-10 * 0.01);
  }
  EXPECT_NEAR(norm(sp.momentum() - (m0 * p.v[0] + m1 * p.v[1])), 0.0, 1e-12 * m0 * 0.01);
}

TEST(Materials, MixedPullOffForce) {
  const DemParams prm = two_materials(false);
  Particles p;
  p.add({0, 0, 0}, kR0, 2500.0);
  p.add({kR0 + kR1, 0, 0}, kR1, 1200.0, {}, 0.0, 1.0, 1);
  DemSystem sys(p, prm);
  const JkrPair jkr = sys.jkr_for(0, 1);
  const double w = 2.0 * std::sqrt(0.01 * 0.04), Rstar = kR0 * kR1 / (kR0 + kR1);
  const double fc = 1.5 * constants::pi * w * Rstar;
  // Pull the pair apart quasi-statically (no velocities) from touching to break: the most tensile
  // normal force is the pull-off force.
  ContactState s;
  double most_tensile = 0.0;
  const double step = 1e-4 * jkr.deltaC;
  for (double delta = jkr.delta_equilibrium(); delta > -1.2 * jkr.deltaC; delta -= step) {
    const PairKinematics k{{0, 0, 0}, {kR0 + kR1 - delta, 0, 0}, {}, {}, {}, {}, kR0, kR1, 1.0, 1.0};
    const PairForce f = sys.contact_law().evaluate_pair(jkr, k, s, sys.dt(), sys.material_pairs().kind(0, 1));
    most_tensile = std::max(most_tensile, f.f_on_i.x);  // f_on_i.x > 0: i pulled towards j
  }
  EXPECT_FALSE(s.active);
  EXPECT_NEAR(most_tensile / fc, 1.0, 1e-6);
  EXPECT_NEAR(jkr.Fc / fc, 1.0, 1e-14);
}

TEST(Materials, MixedStickingVelocity) {
  const DemParams prm = two_materials(false);
  const JkrPair jkr = mixed_closed_form(prm);
  const double m0 = mass(kR0, 2500.0), m1 = mass(kR1, 1200.0), mstar = m0 * m1 / (m0 + m1);
  const double vs0 = 1.3679 * std::sqrt(jkr.Fc * jkr.deltaC / mstar);
  const double vs = bisect([&](double v) { return mixed_pair_sticks(prm, v); }, 0.5 * vs0, 2 * vs0);
  EXPECT_NEAR(vs / vs0, 1.0, 2e-3);
}

TEST(Materials, WallOfAnotherMaterial) {
  // A default-material sphere against a wall of the soft material: R* = r, m* = m, E* and gamma of
  // the pair.
  DemParams prm = two_materials(false);
  Wall w;
  w.normal = {1, 0, 0};
  w.material = WallMaterial::named;
  w.material_id = 1;
  prm.walls = {w};
  const auto& b = prm.materials[0];
  const double estar = 1.0 / ((1 - 0.33 * 0.33) / 1e9 + (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
  const JkrPair jkr = JkrPair::make(kR0, estar, std::sqrt(0.01 * b.surface_energy));
  const double vs0 = 1.3679 * std::sqrt(jkr.Fc * jkr.deltaC / mass(kR0, 2500.0));
  auto sticks = [&](double v) {
    Particles p;
    const double gap = 1e-3 * kR0;
    p.add({kR0 + gap, 0, 0}, kR0, 2500.0, {-v, 0, 0});
    DemSystem sys(p, prm);
    const long max_steps = static_cast<long>((gap / v + 40 * reference_period(sys.particles(), prm)) / sys.dt());
    bool touched = false;
    for (long s = 0; s < max_steps; ++s) {
      sys.step();
      touched = touched || sys.wall_contacts() > 0;
      if (touched && sys.wall_contacts() == 0) return false;
    }
    return touched;
  };
  EXPECT_NEAR(bisect(sticks, 0.5 * vs0, 2 * vs0) / vs0, 1.0, 2e-3);
}

TEST(Materials, NamedCopyOfTheDefaultIsBitIdentical) {
  DemParams one = two_materials(true);
  one.materials.clear();
  DemParams named = one;
  named.materials = {material_of(one.contact, 2500.0, "copy")};
  auto run = [](const DemParams& prm, std::uint32_t mat) {
    Particles p;
    p.add({0, 0, 0}, kR0, 2500.0, {0.05, 0.01, 0}, 0.0, 1.0, mat);
    p.add({2 * kR0 + 1e-8, 0, 0}, kR0, 2500.0, {-0.05, 0, 0}, 0.0, 1.0, 0);
    DemSystem sys(p, prm);
    sys.run(3000);
    return sys.particles();
  };
  const Particles a = run(one, 0), b = run(named, 1);
  for (std::size_t q = 0; q < 2; ++q)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(a.x[q][c], b.x[q][c]);
      EXPECT_EQ(a.w[q][c], b.w[q][c]);
    }
}
