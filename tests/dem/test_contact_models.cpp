// Each contact sub-model alone against its formula (docs/model.md §A.2): the JKR normal model's break
// rules, the alpha(e) damping (and that it dissipates energy), the Ruan & Li friction's two regimes, the
// Marshall sliding spring and its Coulomb cap, the twisting spring and its cap, the rolling spring and
// its moment threshold.
#include <gtest/gtest.h>

#include <cmath>

#include "agglo/core/error.hpp"
#include "agglo/dem/contact/alpha_damping.hpp"
#include "agglo/dem/contact/jkr_normal.hpp"
#include "agglo/dem/contact/marshall_rolling.hpp"
#include "agglo/dem/contact/marshall_sliding.hpp"
#include "agglo/dem/contact/marshall_twisting.hpp"
#include "agglo/dem/contact/ruan_li_friction.hpp"
#include "agglo/dem/contact/tangent_plane.hpp"
#include "agglo/dem/dem_system.hpp"

using namespace agglo;
using namespace agglo::dem;
using namespace agglo::dem::contact;

namespace {

ContactParams params() {
  ContactParams p;  // E = 1 GPa, nu = 0.33, gamma = 0.01 J/m^2, e = 0.7, mu_F = 0.3
  p.rolling_angle = 0.01;
  return p;
}

JkrPair pair_of(const ContactParams& p) { return JkrPair::make(5e-6, p.estar(), p.surface_energy); }

// A contact at the equilibrium radius a0 with normal +x, no damping, time step 1 ns.
ContactPoint point_at_equilibrium(const JkrPair& jkr) {
  ContactPoint c;
  c.n = {1.0, 0.0, 0.0};
  c.a = jkr.a0;
  c.f_ne = jkr.force_of_a(jkr.a0);
  c.f_n = c.f_ne;
  c.dt = 1e-9;
  return c;
}

TEST(ContactModels, JkrNormalBreakRules) {
  auto p = params();
  const auto jkr = pair_of(p);
  p.break_rule = BreakRule::marshall;
  EXPECT_DOUBLE_EQ(JkrNormal(p).break_separation(jkr), jkr.deltaC);
  p.break_rule = BreakRule::lammps;
  const JkrNormal lammps(p);
  EXPECT_NEAR(lammps.break_separation(jkr) / jkr.deltaC, 0.48075, 1e-5);
  // The lammps rule breaks where the force is the pull-off minimum -F_C.
  const double a_break = lammps.contact_radius(jkr, -lammps.break_separation(jkr), 0.0);
  EXPECT_NEAR(lammps.force(jkr, a_break) / jkr.Fc, -1.0, 1e-6);
  EXPECT_NEAR(lammps.force(jkr, jkr.a0), 0.0, 1e-12 * jkr.Fc);
  EXPECT_DOUBLE_EQ(lammps.stiffness(jkr, jkr.a0), 4.0 / 3.0 * jkr.Estar * jkr.a0);
}

TEST(ContactModels, CoefficientsAreChecked) {
  auto p = params();
  p.surface_energy = 0.0;
  try {
    JkrNormal bad(p);
    FAIL() << "no error for gamma = 0";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("surface energy gamma"), std::string::npos) << e.what();
  }
  p = params();
  p.restitution = 1.5;
  EXPECT_THROW(AlphaDamping bad(p), ConfigError);
  p = params();
  p.friction = -0.1;
  EXPECT_THROW(RuanLiFriction bad(p), ConfigError);
  EXPECT_THROW(MarshallSliding bad(p), ConfigError);
  EXPECT_THROW(MarshallTwisting bad(p), ConfigError);
  p = params();
  p.rolling_angle = 0.0;
  EXPECT_THROW(MarshallRolling bad(p), ConfigError);
}

TEST(ContactModels, AlphaDampingCoefficient) {
  auto p = params();
  p.restitution = 0.5;
  const AlphaDamping d(p);
  EXPECT_DOUBLE_EQ(d.alpha(), damping_alpha(0.5));
  EXPECT_DOUBLE_EQ(d.coefficient(2e-12, 300.0), damping_alpha(0.5) * std::sqrt(2e-12 * 300.0));
}

// The damping force opposes the normal relative velocity: its power is negative, approaching or not.
TEST(ContactModels, AlphaDampingDissipates) {
  const auto p = params();
  const auto jkr = pair_of(p);
  ModelNames damped, undamped;
  undamped.damping = "none";
  const ContactLaw with(p, damped), without(p, undamped);
  const double r = 10e-6, m = 1e-11, L = 2 * r - jkr.delta_equilibrium();
  for (double v : {1e-3, -1e-3}) {  // v > 0: approaching
    PairKinematics k{{0, 0, 0}, {L, 0, 0}, {v, 0, 0}, {}, {}, {}, r, r, m, m};
    ContactState s1, s2;
    const Vec3 fd = with.evaluate_pair(jkr, k, s1, 1e-9).f_on_i - without.evaluate_pair(jkr, k, s2, 1e-9).f_on_i;
    const double eta = damping_alpha(p.restitution) * std::sqrt(0.5 * m * jkr.stiffness(s1.a));
    EXPECT_NEAR(fd.x, -eta * v, 1e-12 * eta * std::abs(v));
    EXPECT_LT(dot(fd, k.vi - k.vj), 0.0);
  }
}

// A bonded pair set oscillating about equilibrium keeps its energy without damping and loses it with.
TEST(ContactModels, AlphaDampingDecaysOscillation) {
  auto p = params();
  const auto jkr = pair_of(p);
  const double r = 10e-6, L = 2 * r - jkr.delta_equilibrium();
  auto late_peak_over_early_peak = [&](const char* damping) {
    Particles parts;
    parts.add({-L / 2, 0, 0}, r, 2500.0, {1e-3, 0, 0});
    parts.add({L / 2, 0, 0}, r, 2500.0, {-1e-3, 0, 0});
    DemParams prm;
    prm.contact = p;
    prm.steps_per_period = 200;
    ModelNames names;
    names.damping = damping;
    DemSystem sys(parts, prm, names);
    const long per = 200;  // one reference period
    double early = 0.0, late = 0.0;
    for (long s = 0; s < 10 * per; ++s) {
      sys.step();
      const double ke = sys.kinetic_energy();
      if (s < per) early = std::max(early, ke);
      if (s >= 9 * per) late = std::max(late, ke);
    }
    EXPECT_EQ(sys.active_contacts(), 1);
    return late / early;
  };
  EXPECT_NEAR(late_peak_over_early_peak("none"), 1.0, 0.02);
  EXPECT_LT(late_peak_over_early_peak("alpha"), 0.1);
}

TEST(ContactModels, RuanLiFrictionRegimes) {
  auto p = params();
  const auto jkr = pair_of(p);
  const RuanLiFriction f(p);
  ContactPoint c = point_at_equilibrium(jkr);
  c.f_n = 2e-6;
  c.eta_n = 1e-4;
  ContactState s;
  c.vs = {0, 1e-3, 0};  // viscous: eta |v_s| = 1e-7 < mu F_n = 6e-7
  Vec3 ft = f.force(c, jkr, s);
  EXPECT_NEAR(ft.y, -1e-7, 1e-20);
  EXPECT_EQ(ft.x, 0.0);
  c.vs = {0, 0, -1.0};  // Coulomb: eta |v_s| = 1e-4 > mu F_n
  ft = f.force(c, jkr, s);
  EXPECT_NEAR(ft.z, 0.3 * 2e-6, 1e-18);
  c.vs = {};
  EXPECT_EQ(norm(f.force(c, jkr, s)), 0.0);
}

TEST(ContactModels, MarshallSlidingSpringAndCap) {
  auto p = params();
  const auto jkr = pair_of(p);
  const MarshallSliding f(p);
  ContactPoint c = point_at_equilibrium(jkr);
  c.vs = {0, 1e-2, 0};
  const double kt = 8.0 * p.gstar() * c.a;
  const double flim = p.friction * std::abs(c.f_ne + 2.0 * jkr.Fc);
  ContactState s;
  bool capped = false;
  for (int step = 1; step <= 20000; ++step) {
    const Vec3 ft = f.force(c, jkr, s);
    const double elastic = kt * step * c.vs.y * c.dt;  // spring force while below the cap
    if (elastic <= flim) {
      EXPECT_NEAR(ft.y, -elastic, 1e-9 * flim) << step;
    } else {
      capped = true;
      EXPECT_NEAR(norm(ft), flim, 1e-12 * flim) << step;
      EXPECT_LT(ft.y, 0.0);
      EXPECT_NEAR(ft.y, -kt * s.xi_t.y, 1e-12 * flim);  // spring reset to the force it produces
    }
  }
  EXPECT_TRUE(capped);
}

TEST(ContactModels, SpringFollowsTangentPlane) {
  Vec3 xi{0.0, 3e-9, 4e-9};
  const Vec3 n = Vec3{1.0, 1.0, 0.0} / std::sqrt(2.0);
  rotate_into_plane(xi, n);
  EXPECT_NEAR(dot(xi, n), 0.0, 1e-24);
  EXPECT_NEAR(norm(xi), 5e-9, 1e-22);
}

TEST(ContactModels, MarshallTwistingSpringAndCap) {
  auto p = params();
  const auto jkr = pair_of(p);
  const MarshallTwisting t(p);
  ContactPoint c = point_at_equilibrium(jkr);
  c.w_rel = {1e5, 0.0, 0.0};  // spin about n: the cap is reached after ~80 steps
  const double kq = 0.5 * 8.0 * p.gstar() * c.a * c.a * c.a;
  const double mlim = 2.0 / 3.0 * c.a * p.friction * std::abs(c.f_ne + 2.0 * jkr.Fc);
  ContactState s;
  bool capped = false;
  for (int step = 1; step <= 20000; ++step) {
    const Vec3 m = t.torque(c, jkr, s);
    EXPECT_EQ(m.y, 0.0);
    const double elastic = kq * step * c.w_rel.x * c.dt;
    if (elastic <= mlim) {
      EXPECT_NEAR(m.x, -elastic, 1e-9 * mlim) << step;
    } else {
      capped = true;
      EXPECT_NEAR(m.x, -mlim, 1e-12 * mlim) << step;
    }
  }
  EXPECT_TRUE(capped);
}

TEST(ContactModels, MarshallRollingThreshold) {
  auto p = params();
  const auto jkr = pair_of(p);
  const MarshallRolling r(p);
  ContactPoint c = point_at_equilibrium(jkr);
  c.w_rel = {0.0, 0.0, 1e5};  // rolling about z: xi_R grows along +y, capped after 100 steps
  const double kr = 4.0 * jkr.Fc;  // (a/a0)^(3/2) = 1
  const double m_max = kr * p.rolling_angle * jkr.R;
  ContactState s;
  bool capped = false;
  for (int step = 1; step <= 2000; ++step) {
    const Vec3 m = r.torque(c, jkr, s);
    const double xi = jkr.R * c.dt * c.w_rel.z * step;
    EXPECT_NEAR(m.z, -kr * std::min(xi, p.rolling_angle * jkr.R), 1e-9 * m_max) << step;  // opposes w_rel
    EXPECT_LE(norm(m), m_max * (1 + 1e-12));
    capped = capped || xi > p.rolling_angle * jkr.R;
  }
  EXPECT_TRUE(capped);
}

}  // namespace
