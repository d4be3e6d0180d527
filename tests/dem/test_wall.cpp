// Sphere-wall contact (dem/wall.hpp, docs/model.md §A.5): sticking velocities found by bisection on
// the DEM against the closed form 1.3679 sqrt(F_C delta_C / m*) with the wall's R* = r, m* = m, the
// wall/pair ratio 2^(1/6) for the same material (undamped and damped), the seed material's values,
// a wall at an oblique orientation, and a sphere resting on a wall.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "agglo/dem/contact/builtin_models.hpp"
#include "agglo/dem/contact_law.hpp"

#include "sticking.hpp"

using namespace agglo;
using namespace agglo::dem;
using namespace agglo::dem::testing;

namespace {

// sqrt(2 x 0.935503) = 1.36785: the undamped capture velocity in units of sqrt(F_C delta_C / m*).
const double kCapture = std::sqrt(2.0 * 0.935503);

// Runs until the contact (sphere-sphere or sphere-wall) has broken or 40 contact periods have passed;
// true if it stayed.
bool stays(DemSystem& sys, double approach_time) {
  const long max_steps = static_cast<long>((approach_time + 40 * reference_period(sys.particles(), sys.params())) / sys.dt());
  bool touched = false;
  for (long s = 0; s < max_steps; ++s) {
    sys.step();
    const bool active = sys.active_contacts() + sys.wall_contacts() > 0;
    touched = touched || active;
    if (touched && !active) return false;
  }
  EXPECT_TRUE(touched);
  return true;
}

// A sphere approaching `wall` along -normal at speed v from a gap of 1e-3 r.
bool sticks_to_wall(const Sample& m, DemParams prm, const Wall& wall, double v) {
  prm.walls = {wall};
  const double gap = 1e-3 * m.r;
  Particles p;
  p.add(wall.point + (m.r + gap) * wall.normal, m.r, m.rho, -v * wall.normal);
  DemSystem sys(p, prm);
  return stays(sys, gap / v);
}

// Two equal spheres head-on at relative speed v.
bool pair_sticks(const Sample& m, const DemParams& prm, double v) {
  const double gap = 1e-3 * m.r;
  Particles p;
  p.add({-(m.r + gap / 2), 0, 0}, m.r, m.rho, {v / 2, 0, 0});
  p.add({m.r + gap / 2, 0, 0}, m.r, m.rho, {-v / 2, 0, 0});
  DemSystem sys(p, prm);
  return stays(sys, gap / v);
}

// Closed form with R* = r, m* = m and the wall's E*.
double wall_capture(const Sample& m, WallMaterial w) {
  const auto jkr = JkrPair::make(m.r, wall_estar(w, m.E, m.nu), m.gamma);
  return kCapture * std::sqrt(jkr.Fc * jkr.deltaC / m.mass());
}

double pair_capture(const Sample& m) {
  const auto jkr = JkrPair::make(m.r / 2, m.E / (2 * (1 - m.nu * m.nu)), m.gamma);
  return kCapture * std::sqrt(jkr.Fc * jkr.deltaC / (m.mass() / 2));
}

Wall wall_of(WallMaterial mat, Vec3 normal = {1, 0, 0}) {
  Wall w;
  w.point = {1e-5, -2e-5, 3e-5};
  w.normal = normal / norm(normal);
  w.material = mat;
  return w;
}

double wall_sticking(const Sample& m, const DemParams& prm, const Wall& w, double lo, double hi) {
  return bisect([&](double v) { return sticks_to_wall(m, prm, w, v); }, lo, hi);
}

TEST(Wall, EffectiveModulus) {
  EXPECT_DOUBLE_EQ(wall_estar(WallMaterial::same, 1e9, 0.33), 1e9 / (2 * (1 - 0.33 * 0.33)));
  EXPECT_DOUBLE_EQ(wall_estar(WallMaterial::rigid, 1e9, 0.33), 1e9 / (1 - 0.33 * 0.33));
}

TEST(Wall, SeedMaterialClosedForm) {
  // The values quoted by issue 24 for the seed material (E = 1 GPa): 0.02514 m/s (same), 0.01996 m/s (rigid).
  const Sample m;
  EXPECT_NEAR(wall_capture(m, WallMaterial::same), 0.02514, 5e-6);
  EXPECT_NEAR(wall_capture(m, WallMaterial::rigid), 0.01996, 5e-6);
  EXPECT_NEAR(wall_capture(m, WallMaterial::same) / pair_capture(m), std::pow(2.0, 1.0 / 6.0), 1e-12);
}

TEST(Wall, UndampedStickingSameMaterial) {
  const Sample m;
  const double vs0 = wall_capture(m, WallMaterial::same);
  const double vs = wall_sticking(m, params_for(m, 0.7, false), wall_of(WallMaterial::same), 0.5 * vs0, 2 * vs0);
  EXPECT_NEAR(vs / vs0, 1.0, 2e-3);
  EXPECT_NEAR(vs, 0.02514, 2e-3 * 0.02514);
  // The pair in the same DEM: the ratio 2^(1/6).
  const auto prm = params_for(m, 0.7, false);
  const double vp = bisect([&](double v) { return pair_sticks(m, prm, v); }, 0.5 * pair_capture(m), 2 * pair_capture(m));
  std::printf("same-material wall: v_s = %.6g m/s (closed form %.6g), pair %.6g m/s, ratio %.6g\n", vs, vs0, vp, vs / vp);
  EXPECT_NEAR(vs / vp, std::pow(2.0, 1.0 / 6.0), 2e-3);
}

TEST(Wall, UndampedStickingRigid) {
  const Sample m;
  const double vs0 = wall_capture(m, WallMaterial::rigid);
  const double vs = wall_sticking(m, params_for(m, 0.7, false), wall_of(WallMaterial::rigid), 0.5 * vs0, 2 * vs0);
  std::printf("rigid wall: v_s = %.6g m/s (closed form %.6g)\n", vs, vs0);
  EXPECT_NEAR(vs / vs0, 1.0, 2e-3);
  EXPECT_NEAR(vs, 0.01996, 2e-3 * 0.01996);
}

TEST(Wall, ObliqueWallSameSticking) {
  // The wall's orientation and position do not matter: a normal along (1, -2, 0.5).
  const Sample m{3e-6, 1200, 3e9, 0.25, 0.03};
  const double vs0 = wall_capture(m, WallMaterial::same);
  const double vs =
      wall_sticking(m, params_for(m, 0.7, false), wall_of(WallMaterial::same, {1, -2, 0.5}), 0.5 * vs0, 2 * vs0);
  EXPECT_NEAR(vs / vs0, 1.0, 2e-3);
}

TEST(Wall, DampedRatioFollowsAlpha) {
  // With eta_N = alpha(e) sqrt(m* k_N) the dimensionless contact depends on e only, so the damped
  // sticking velocity is g(e) times the undamped one (docs/model.md §A.4 item 6) and the wall/pair
  // ratio stays 2^(1/6).
  const Sample m;
  const std::pair<double, double> table[] = {{0.9, 1.275}, {0.5, 3.123}};
  for (auto [e, g] : table) {
    const auto prm = params_for(m, e, true);
    const double vw0 = wall_capture(m, WallMaterial::same), vp0 = pair_capture(m);
    const double vw = wall_sticking(m, prm, wall_of(WallMaterial::same), vw0, 8 * vw0);
    const double vp = bisect([&](double v) { return pair_sticks(m, prm, v); }, vp0, 8 * vp0);
    std::printf("e = %g: wall v_s/v_s0 = %.5g (g(e) = %g), wall/pair = %.6g\n", e, vw / vw0, g, vw / vp);
    EXPECT_NEAR(vw / vw0, g, 5e-3 * g) << "e = " << e;
    EXPECT_NEAR(vw / vp, std::pow(2.0, 1.0 / 6.0), 2e-3) << "e = " << e;
  }
}

TEST(Wall, SphereAtEquilibriumStaysAtRest) {
  Sample m;
  auto prm = params_for(m, 0.7, true);
  prm.contact.friction = 0.3;
  const Wall w = wall_of(WallMaterial::rigid, {0, 0, 1});
  prm.walls = {w};
  const auto jkr = JkrPair::make(m.r, wall_estar(w.material, m.E, m.nu), m.gamma);
  const Vec3 x0 = w.point + (m.r - jkr.delta_equilibrium()) * w.normal;
  Particles p;
  p.add(x0, m.r, m.rho);
  DemSystem sys(p, prm);
  sys.run(20000);
  EXPECT_EQ(sys.wall_contacts(), 1);
  EXPECT_LT(norm(sys.particles().v[0]), 1e-12);
  EXPECT_LT(norm(sys.particles().x[0] - x0), 1e-6 * jkr.deltaC);
}

TEST(Wall, ObliqueImpactFrictionSpinsSphere) {
  // A sphere hitting a wall obliquely with Marshall's sliding friction: the tangential force at the
  // contact point slows the sliding and spins the sphere the way it would roll.
  Sample m;
  auto prm = params_for(m, 0.7, true);
  prm.contact.friction = 0.5;
  prm.contact.models.tangential = contact::MarshallSliding::name;
  const Wall w = wall_of(WallMaterial::same, {0, 0, 1});
  prm.walls = {w};
  Particles p;
  const double v = 0.5 * wall_capture(m, WallMaterial::same);
  p.add(w.point + (m.r + 1e-3 * m.r) * w.normal, m.r, m.rho, {v, 0, -v});
  DemSystem sys(p, prm);
  sys.run(40000);
  // Sliding along +x on a wall below: friction along -x at the contact (below the centre) spins it
  // about +y, as rolling would.
  EXPECT_GT(sys.particles().w[0].y, 0.0);
  EXPECT_LT(sys.particles().v[0].x, v);
}

}  // namespace

// The fast path's wall sums (ContactKernel::accumulate_wall: only spheres in contact added, no buffer) equal
// the reference's (evaluate_wall into a buffer, then every sphere's entry added) bit for bit, forces, torques
// and states, for spheres apart, touching, pressed in, held in tension and breaking, under the built-in model
// sets; the negative control is the same comparison after the forces of one sphere changed by 1e-12.
TEST(Wall, AccumulateEqualsBufferedSums) {
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Wall w = wall_of(WallMaterial::same, {0.3, -0.2, 1.0});
  const double r = 10e-6;
  Particles p;
  WallContacts wc;
  ContactParams prm;
  for (int k = 0; k < 200; ++k) {
    const double gap = (k % 5 == 0) ? 0.2 * r : 2e-3 * r * u(gen);  // a fifth far apart, the rest near contact
    p.add(w.point + Vec3{u(gen), u(gen), 0.0} * 1e-4 + (r + gap) * w.normal, r, 2500.0,
          Vec3{u(gen), u(gen), u(gen)} * 0.01);
    p.w.back() = Vec3{u(gen), u(gen), u(gen)} * 1e3;
    p.f.back() = Vec3{u(gen), u(gen), u(gen)} * 1e-6;  // forces of the pairs already summed
    p.t.back() = Vec3{u(gen), u(gen), u(gen)} * 1e-12;
    ContactState s;
    s.active = gen() % 2 == 0;
    if (s.active) s.xi_t = Vec3{u(gen), u(gen), u(gen)} * 1e-9;
    wc.state.push_back(s);
    wc.jkr.push_back(JkrPair::make(r, wall_estar(w.material, prm.youngs_modulus, prm.poisson_ratio), prm.surface_energy));
    wc.kind.push_back(0);
  }
  auto same = [](const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (const char* tangential : {contact::RuanLiFriction::name, contact::MarshallSliding::name}) {
    contact::ModelNames names;
    names.tangential = tangential;
    const ContactLaw law(prm, names);
    Particles a = p, b = p;
    WallContacts wa = wc, wb = wc;
    law.accumulate_wall(w, wa, a, 2e-9);
    std::vector<PairForce> out;
    law.evaluate_wall(w, wb, b, 2e-9, out);
    for (std::size_t q = 0; q < b.size(); ++q) b.f[q] += out[q].f_on_i, b.t[q] += out[q].t_on_i;
    int diff = 0, touching = 0;
    for (std::size_t q = 0; q < a.size(); ++q) {
      diff += !same(a.f[q], b.f[q]) + !same(a.t[q], b.t[q]) + !same(wa.state[q].xi_t, wb.state[q].xi_t) +
              (wa.state[q].active != wb.state[q].active) + (std::memcmp(&wa.state[q].delta, &wb.state[q].delta, 8) != 0);
      touching += wa.state[q].active;
    }
    EXPECT_EQ(diff, 0) << tangential;
    EXPECT_GT(touching, 50) << "the comparison needs spheres in contact";
    EXPECT_LT(touching, 190) << "and spheres apart";
    b.f[7].x *= 1.0 + 1e-12;  // negative control
    EXPECT_FALSE(same(a.f[7], b.f[7]));
  }
}
