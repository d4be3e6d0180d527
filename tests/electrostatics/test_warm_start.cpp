// Solver warm starts for checkpoints (solver.hpp: warm_start / set_warm_start): a fresh solver given
// the warm start of another solves the next problem bitwise identically to it, while a fresh solver
// without it (a cold start) differs, so the warm start is state a restart must carry.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "agglo/electrostatics/solver.hpp"

using namespace agglo;
using namespace agglo::es;

namespace {

constexpr double kRadius = 10e-6;   // [m]
constexpr double kCharge = 1e-14;  // [C]

Problem three_spheres(double shift) {
  Problem p;
  p.spheres = {Sphere{{0, 0, 0}, kRadius, kCharge, 15}, Sphere{{2.2 * kRadius + shift, 0, 0}, kRadius, -kCharge, 15},
               Sphere{{kRadius, 2.1 * kRadius, shift}, kRadius, kCharge, 15}};
  return p;
}

bool bitwise_equal(const Solution& a, const Solution& b) {
  return a.force.size() == b.force.size() && a.energy == b.energy &&
         std::memcmp(a.force.data(), b.force.data(), a.force.size() * sizeof(Vec3)) == 0 &&
         std::memcmp(a.torque.data(), b.torque.data(), a.torque.size() * sizeof(Vec3)) == 0;
}

void check(const SolverOptions& o) {
  auto first = make_solver(o);
  first->solve(three_spheres(0.0));
  const WarmStart w = first->warm_start();
  EXPECT_FALSE(w.values.empty());
  auto second = make_solver(o);
  second->set_warm_start(w);
  auto cold = make_solver(o);
  const Problem next = three_spheres(0.02 * kRadius);
  const Solution a = first->solve(next), b = second->solve(next), c = cold->solve(next);
  EXPECT_TRUE(bitwise_equal(a, b)) << o.solver << ": the restored warm start gives another solution";
  EXPECT_FALSE(bitwise_equal(a, c)) << o.solver << ": a cold start gives the same bits (test has no power)";
  EXPECT_EQ(a.stats.iterations, b.stats.iterations);
}

}  // namespace

TEST(WarmStart, SpectralRestoredSolvesBitwiseIdentically) {
  SolverOptions o;
  o.solver = "spectral";
  o.target_accuracy = 1e-3;
  check(o);
}

TEST(WarmStart, BemRestoredSolvesBitwiseIdentically) {
  SolverOptions o;
  o.solver = "bem";
  o.patches_per_sphere = 200;
  o.matvec = "fmm";  // the default; "direct" sums per-thread partial sums of a dynamic schedule, so with
                     // more than one thread its solves are not bitwise reproducible even without a restart
  check(o);
}
