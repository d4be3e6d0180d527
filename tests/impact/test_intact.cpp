// Intact for good (impact/intact.hpp, contact_barrier.hpp): the closed-form JKR potential against the
// integral of the force, the loaded barrier against its definition, the criterion on hand-made states
// of the seed tetrahedron (at rest, vibrating, with the projectile coming or gone, under pair and
// non-pair electrostatic forces), and whole impacts decided early with the outcome of the full run.
#include <gtest/gtest.h>

#include <cmath>

#include "agglo/core/config.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/impact/agglomerate.hpp"
#include "agglo/impact/contact_barrier.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/impact/intact.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace intact_test {

ImpactCase load_case(const std::string& name) {
  Config cfg = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/" + name);
  return parse_impact_case(cfg);
}

// Work of the JKR force from a1 to a2 along the stable branch, F d(delta), by the midpoint rule [J].
double force_work(const dem::JkrPair& j, double a1, double a2) {
  const int n = 200000;
  double w = 0.0;
  for (int k = 0; k < n; ++k) {
    const double a = a1 + (a2 - a1) * (k + 0.5) / n, da = (a2 - a1) / n;
    w += j.force_of_a(a) * (j.delta_of_a(a + 0.5 * da) - j.delta_of_a(a - 0.5 * da));
  }
  return w;
}

// The seed tetrahedron (neutral case) at rest with its contacts evaluated.
dem::DemSystem tetrahedron(const ImpactCase& c) {
  dem::DemSystem sys(build_agglomerate(c), c.dem);
  sys.compute_forces();
  return sys;
}

double unit_energy(const dem::DemSystem& sys) {
  const auto j = sys.jkr_for(0, 1);
  return j.Fc * j.deltaC;
}

}  // namespace intact_test

using intact_test::unit_energy;

TEST(ContactBarrier, PotentialIsTheIntegralOfTheForce) {
  const auto j = dem::JkrPair::make(5e-6, 2.08e8, 0.01);
  const double xb = break_x(1.0), x0 = formation_x();
  for (double x : {xb, x0, 1.0, 1.7}) {
    const double w = intact_test::force_work(j, 0.8 * j.a0, x * j.a0) / (j.Fc * j.deltaC);
    EXPECT_NEAR(jkr_potential(x) - jkr_potential(0.8), w, 1e-6) << x;
  }
  EXPECT_NEAR(j.delta_of_a(xb * j.a0), -j.deltaC, 1e-9 * j.deltaC);
  EXPECT_NEAR(j.delta_of_a(x0 * j.a0), 0.0, 1e-9 * j.deltaC);
  EXPECT_NEAR(j.delta_of_a(break_x(-dem::kDeltaAtMinForce) * j.a0), dem::kDeltaAtMinForce * j.deltaC, 1e-7 * j.deltaC);
}

TEST(ContactBarrier, LoadedBarrier) {
  const auto free = loaded_contact(0.0, 1.0);  // unloaded: equilibrium a = a0, barrier to -delta_C
  EXPECT_NEAR(free.x_min, 1.0, 1e-12);
  EXPECT_NEAR(free.barrier, 1.5426, 1e-4);  // Marshall's rule: work from equilibrium to -delta_C
  double last = 1e9;
  for (double l : {0.5, 0.2, 0.0, -0.3, -0.6, -0.8, -0.95}) {  // pushing apart lowers the barrier
    const auto c = loaded_contact(l, 1.0);
    EXPECT_NEAR(4.0 * (std::pow(c.x_min, 3) - std::pow(c.x_min, 1.5)), l, 1e-9);  // F = L at the minimum
    EXPECT_LT(c.barrier, last);
    EXPECT_GT(c.barrier, 0.0);
    // The barrier is the largest rise of psi on a grid between the break point and the minimum.
    double peak = -1e9;
    for (int k = 0; k <= 4000; ++k) {
      const double x = break_x(1.0) + (c.x_min - break_x(1.0)) * k / 4000.0;
      peak = std::max(peak, loaded_potential(x, l));
    }
    EXPECT_NEAR(c.barrier, peak - loaded_potential(c.x_min, l), 1e-6);
    last = c.barrier;
  }
  EXPECT_EQ(loaded_contact(-1.0, 1.0).barrier, 0.0);
  EXPECT_LT(loaded_contact(0.0, -dem::kDeltaAtMinForce).barrier, free.barrier);  // "lammps": breaks sooner
}

TEST(Intact, TetrahedronAtRestAndVibrating) {
  const ImpactCase c = intact_test::load_case("seed000_neutral_tetrahedron.toml");
  auto sys = intact_test::tetrahedron(c);
  const auto rest = intact_bound(sys, 4, nullptr, 1.0);
  EXPECT_TRUE(rest.intact()) << rest.failed;
  // Two primaries moving apart with a relative kinetic energy of 3 F_C delta_C: could break a contact.
  auto& p = sys.particles();
  const double u = unit_energy(sys), v = std::sqrt(3.0 * u / p.m[0]);  // 2 x 1/2 m v^2 = ... with mu = m/2
  const Vec3 e = (p.x[1] - p.x[0]) / norm(p.x[1] - p.x[0]);
  p.v[0] = -v * e, p.v[1] = v * e;
  const auto shaken = intact_bound(sys, 4, nullptr, 1.0);
  EXPECT_TRUE(shaken.applies);
  EXPECT_FALSE(shaken.intact());
  // The same energy in a rigid rotation is kept by the angular momentum (bound B).
  const Vec3 axis{0.0, 0.0, 1.0};
  Vec3 xc;
  for (std::size_t k = 0; k < 4; ++k) xc += p.x[k] / 4.0;
  for (std::size_t k = 0; k < 4; ++k) p.v[k] = (v / norm(p.x[0] - xc)) * cross(axis, p.x[k] - xc), p.w[k] = {};
  double spin = 0.0;
  for (std::size_t k = 0; k < 4; ++k) spin += 0.5 * p.m[k] * norm2(p.v[k]);
  ASSERT_GT(spin, 2.0 * u);
  for (std::size_t k = 0; k < 4; ++k) p.w[k] = (v / norm(p.x[0] - xc)) * axis;
  EXPECT_TRUE(intact_bound(sys, 4, nullptr, 1.0).intact());
}

TEST(Intact, ProjectileComingOrGone) {
  const ImpactCase c = intact_test::load_case("seed000_neutral_tetrahedron.toml");
  dem::Particles tmp = build_agglomerate(c);
  add_projectile(tmp, c, 0.17);  // one radius in front, moving onto the agglomerate
  dem::DemSystem sys(tmp, c.dem);
  sys.compute_forces();
  const auto coming = intact_bound(sys, 4, nullptr, 1.0);
  EXPECT_FALSE(coming.intact());  // its kinetic energy could break the agglomerate
  sys.particles().v[4] = -sys.particles().v[4];
  const auto gone = intact_bound(sys, 4, nullptr, 1.0);
  EXPECT_TRUE(gone.intact()) << gone.failed;
  sys.particles().q[4] = 1e-15;  // a charged projectile is not left out with electrostatics
  const std::vector<Vec3> none(5);
  EXPECT_FALSE(intact_bound(sys, 4, &none, 1.0).intact());
}

TEST(Intact, ElectrostaticForcesMustBePairForces) {
  const ImpactCase c = intact_test::load_case("seed000_neutral_tetrahedron.toml");
  auto sys = intact_test::tetrahedron(c);
  const auto& p = sys.particles();
  // Coulomb forces of +,+,-,- charges: internal pair forces, a tenth of F_C.
  const double fc = sys.jkr_for(0, 1).Fc, q[4] = {1.0, 1.0, -1.0, -1.0};
  std::vector<Vec3> f(4);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t k = 0; k < 4; ++k)
      if (k != i) f[i] += (0.1 * fc * q[i] * q[k] * 4.0 * p.r[0] * p.r[0] / norm2(p.x[i] - p.x[k])) *
                          (p.x[i] - p.x[k]) / norm(p.x[i] - p.x[k]);
  const auto paired = intact_bound(sys, 4, &f, 1.0);
  EXPECT_TRUE(paired.intact()) << paired.failed;
  for (auto& fk : f) fk += Vec3{0.05 * fc, 0.0, 0.0};  // an applied field's net force
  const auto field = intact_bound(sys, 4, &f, 1.0);
  EXPECT_FALSE(field.applies);
}

TEST(Intact, ImpactsDecidedEarlyKeepTheirOutcome) {
  // Neutral at 0.02 m/s: the projectile stays attached (bound A); kappa_p = 1 at 0.1255 m/s: the
  // tetrahedron stays rigid and the projectile leaves (bound B, Coulomb loads); 0.25 m/s breaks both.
  struct Impact {
    const char* name;
    double v;
    bool early;
  };
  for (const Impact& i : {Impact{"seed000_neutral_tetrahedron.toml", 0.02, true},
                          Impact{"seed000_neutral_tetrahedron.toml", 0.25, false},
                          Impact{"seed000_charged_tetrahedron_k1.toml", 0.1255, true},
                          Impact{"seed000_charged_tetrahedron_k1.toml", 0.25, false}}) {
    ImpactCase full = intact_test::load_case(i.name), early = full;
    full.time.intact_stop = "off";
    early.time.intact_stop = "on";
    const auto a = run_impact(full, i.v), b = run_impact(early, i.v);
    EXPECT_EQ(a.broken, b.broken) << i.name << " " << i.v;
    EXPECT_EQ(a.undecided, b.undecided) << i.name << " " << i.v;
    EXPECT_EQ(a.breakage.fragment_sizes, b.breakage.fragment_sizes) << i.name << " " << i.v;
    if (i.early) {
      EXPECT_FALSE(a.early_stop);
      EXPECT_TRUE(b.early_stop);
      EXPECT_LT(b.steps, a.steps / 2) << i.name << " " << i.v;  // decided well before the end
    } else {
      EXPECT_EQ(a.steps, b.steps) << i.name << " " << i.v;  // broken: the clearly-broken stop, unchanged
    }
  }
}
