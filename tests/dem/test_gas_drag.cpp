// Gas drag and gravity in the DEM (dem/gas_drag.hpp, docs/model.md §A.6): a sphere released at speed v
// in still gas decays as exp(-t/tau), tau = m C_c / (3 pi mu d), a falling sphere reaches the settling
// velocity g tau, a sphere in a uniform flow takes the flow's velocity; the shared gas formulas
// (core/gas_law.hpp) against textbook values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "agglo/core/gas_law.hpp"
#include "agglo/dem/dem_system.hpp"

using namespace agglo;
using namespace agglo::dem;

namespace {

constexpr double kR = 1e-6, kRho = 2000.0, kMu = 1.8e-5, kLambda = 65e-9;

DemParams gas_params() {
  DemParams p;
  p.gas.enabled = true;
  p.gas.viscosity = kMu;
  p.gas.mean_free_path = kLambda;
  return p;
}

// tau written out here (not through GasDrag): m C_c / (3 pi mu d), C_c = 1 + Kn (1.257 + 0.4 e^(-1.1/Kn)).
double expected_tau() {
  const double d = 2 * kR, kn = 2 * kLambda / d;
  const double cc = 1 + kn * (1.257 + 0.4 * std::exp(-1.1 / kn));
  const double m = 4.0 / 3.0 * constants::pi * kR * kR * kR * kRho;
  return m * cc / (3 * constants::pi * kMu * d);
}

TEST(GasDrag, RelaxationTime) {
  GasDrag g = gas_params().gas;
  const double m = 4.0 / 3.0 * constants::pi * kR * kR * kR * kRho;
  EXPECT_NEAR(g.relaxation_time(m, kR) / expected_tau(), 1.0, 1e-14);
}

TEST(GasDrag, ReleasedSphereDecaysExponentially) {
  const double tau = expected_tau();
  for (double steps_per_tau : {20.0, 1000.0}) {
    auto prm = gas_params();
    prm.dt = tau / steps_per_tau;
    Particles p;
    const Vec3 v0{0.3, -0.1, 0.05};
    p.add({0, 0, 0}, kR, kRho, v0);
    DemSystem sys(p, prm);
    for (int k = 0; k < 3; ++k) {
      sys.run(static_cast<long>(steps_per_tau));
      const Vec3 want = std::exp(-sys.time() / tau) * v0;
      const double err = norm(sys.particles().v[0] - want) / norm(want);
      std::printf("dt = tau/%g, t = %g tau: relative error %.3g\n", steps_per_tau, sys.time() / tau, err);
      EXPECT_LT(err, 1e-6) << "t = " << sys.time();
    }
  }
}

TEST(GasDrag, FallingSphereReachesSettlingVelocity) {
  const double tau = expected_tau();
  auto prm = gas_params();
  prm.gravity = {0, 0, -constants::g0};
  prm.dt = tau / 50;
  Particles p;
  p.add({0, 0, 0}, kR, kRho);
  DemSystem sys(p, prm);
  sys.run(50 * 30);  // 30 tau
  const double vs = constants::g0 * tau;  // settling velocity
  EXPECT_NEAR(sys.particles().v[0].z / -vs, 1.0, 1e-6);
  EXPECT_NEAR(sys.particles().v[0].x, 0.0, 1e-15);
  // Without drag the same sphere falls freely: v = g t.
  prm.gas.enabled = false;
  DemSystem free(p, prm);
  free.run(100);
  EXPECT_NEAR(free.particles().v[0].z / (-constants::g0 * free.time()), 1.0, 1e-12);
}

TEST(GasDrag, SphereTakesTheFlowVelocity) {
  const double tau = expected_tau();
  auto prm = gas_params();
  prm.gas.flow = {0.2, 0.0, -0.1};
  prm.dt = tau / 50;
  Particles p;
  p.add({0, 0, 0}, kR, kRho);
  DemSystem sys(p, prm);
  sys.run(50 * 40);
  EXPECT_LT(norm(sys.particles().v[0] - prm.gas.flow), 1e-6 * norm(prm.gas.flow));
}

TEST(GasLaw, AirAtRoomConditions) {
  // Air at 293.15 K, 101325 Pa: mu = 1.81e-5 Pa s, rho = 1.204 kg/m^3, lambda ~ 66 nm (Hinds 1999, tables).
  const double T = 293.15, P = 101325;
  const double mu = gas::sutherland_viscosity(T), rho = gas::density(T, P);
  EXPECT_NEAR(mu, 1.81e-5, 0.01e-5);
  EXPECT_NEAR(rho, 1.204, 0.002);
  EXPECT_NEAR(gas::mean_free_path(mu, rho, gas::mean_speed(T)), 66e-9, 2e-9);
  // The two limits of C_c: 1 + 1.257 Kn for Kn -> 0, 1 + 1.657 Kn for Kn -> infinity.
  EXPECT_NEAR((gas::cunningham(1e-3, 66e-9) - 1) / (1.257 * 2 * 66e-9 / 1e-3), 1.0, 1e-9);
  EXPECT_NEAR((gas::cunningham(1e-9, 66e-9) - 1) / (1.657 * 2 * 66e-9 / 1e-9), 1.0, 1e-2);
}

}  // namespace
