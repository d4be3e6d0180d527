// Grounded conducting wall (wall.grounded; impact/electrostatic_coupling.hpp): the force on a charged
// sphere near the plane against the image-charge law q^2/(16 pi eps0 h^2) (exact for point charges,
// at large h with polarisation) and against agglo's own solve of the two-sphere problem with the
// opposite-charge mirror sphere at the mirror distance; the energy is half the mirrored system's.
#include <gtest/gtest.h>

#include <cmath>

#include "agglo/electrostatics/config.hpp"
#include "agglo/electrostatics/solver.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

constexpr double kR = 10e-6;
const double kQ = 1e-5 * 4 * constants::pi * kR * kR;

dem::Wall oblique_wall() {
  dem::Wall w;
  w.point = {3e-6, -1e-6, 2e-6};
  w.normal = Vec3{0.3, -0.4, 0.866} / norm(Vec3{0.3, -0.4, 0.866});
  return w;
}

CouplingSettings settings(const std::string& solver, double kappa0 = 1.0) {
  CouplingSettings s;
  s.es.options.solver = solver;
  s.es.options.target_accuracy = 1e-6;
  s.es.medium_permittivity = kappa0;
  s.grounded = {oblique_wall()};
  return s;
}

struct Result {
  Vec3 force;
  double energy;
};

Result near_wall(const CouplingSettings& s, double h, double kappa) {
  const auto& w = s.grounded.front();
  dem::Particles p;
  p.add(w.point + h * w.normal, kR, 2500, {}, kQ, kappa);
  ElectrostaticForce f(s);
  std::vector<Vec3> F(1), T(1);
  f.add_forces(p, 0, 0.0, F, T);
  return {F[0], f.energy()};
}

double near_wall_energy_alone(const CouplingSettings& s, const dem::Wall& w, double h) {
  dem::Particles p;
  p.add(w.point + h * w.normal, kR, 2500, {}, kQ, 1.0);
  ElectrostaticForce f(s);
  std::vector<Vec3> F(1), T(1);
  f.add_forces(p, 0, 0.0, F, T);
  return f.energy();
}

TEST(ImageCharges, PointChargeLawExact) {
  // kappa_p = kappa_0 = 1: point charges, the image law holds at every height.
  const auto s = settings("spectral");
  const auto& n = s.grounded.front().normal;
  for (double h : {1.1 * kR, 3 * kR, 50 * kR}) {
    const auto r = near_wall(s, h, 1.0);
    const double f_ref = kQ * kQ / (16 * constants::pi * constants::eps0 * h * h);
    EXPECT_NEAR(dot(r.force, n) / -f_ref, 1.0, 1e-12) << "h = " << h;  // attracted to the wall
    EXPECT_LT(norm(r.force - dot(r.force, n) * n), 1e-12 * f_ref);
    // The solvers' energy includes each sphere's self energy: without the wall, the same sphere alone.
    auto alone = s;
    alone.grounded.clear();
    const double interaction = r.energy - near_wall_energy_alone(alone, s.grounded.front(), h);
    EXPECT_NEAR(interaction / (-kQ * kQ / (16 * constants::pi * constants::eps0 * h)), 1.0, 1e-9);
  }
}

TEST(ImageCharges, DielectricSphereFarFromWall) {
  // kappa_p = 15: polarisation adds O((r/h)^3) relative to the image law.
  const auto s = settings("spectral");
  const auto& n = s.grounded.front().normal;
  const double h = 40 * kR;
  const auto r = near_wall(s, h, 15.0);
  const double f_ref = kQ * kQ / (16 * constants::pi * constants::eps0 * h * h);
  EXPECT_NEAR(dot(r.force, n) / -f_ref, 1.0, 1e-3);
}

TEST(ImageCharges, MatchesTwoSphereSolveAtMirrorDistance) {
  for (double kappa : {2.5, 15.0}) {
    const auto s = settings("spectral");
    const auto& w = s.grounded.front();
    for (double h : {1.02 * kR, 1.5 * kR}) {
      const auto r = near_wall(s, h, kappa);
      // The two-sphere problem: the sphere and an opposite charge at the mirror point, 2h apart.
      const Vec3 x = w.point + h * w.normal;
      const auto prob = es::make_problem(s.es, {x, x - 2 * h * w.normal}, {kR, kR}, {kQ, -kQ}, {kappa, kappa});
      const auto two = es::make_solver(s.es.options)->solve(prob);
      EXPECT_LT(norm(r.force - two.force[0]), 1e-9 * norm(two.force[0])) << "kappa " << kappa << " h " << h;
      EXPECT_NEAR(r.energy, 0.5 * two.energy, 1e-9 * std::abs(two.energy));
      // Stronger than the image law of a point charge: the sphere polarises near its image.
      const double f_ref = kQ * kQ / (16 * constants::pi * constants::eps0 * h * h);
      EXPECT_GT(norm(r.force), f_ref) << "kappa " << kappa << " h " << h;
    }
  }
}

}  // namespace
