// The tabulated isolated-pair solutions agree with direct two-sphere solves between table nodes.
#include <gtest/gtest.h>

#include <cmath>

#include "agglo/impact/pair_table.hpp"

using namespace agglo;
using namespace agglo::impact;

TEST(PairTable, MatchesDirectSolvesBetweenNodes) {
  es::SolverOptions opt;
  opt.solver = "spectral";
  opt.target_accuracy = 1e-6;
  const double r = 10e-6 / 1.005;
  for (double kappa : {2.5, 15.0}) {
    PairKey key{r, r, kappa, 1.0, 1.0};
    PairTable t(opt, key, 1e-3 * r, 50 * r, 97);
    auto solver = es::make_solver(opt);
    for (double hr : {0.0031, 0.0097, 0.0213, 0.077, 0.31, 1.7, 12.0}) {
      double h = hr * r;
      for (auto [qi, qj] : {std::pair{1e-14, 0.0}, {0.0, 1e-14}, {1e-14, -2e-14}, {-3e-14, 1e-14}}) {
        es::Problem p;
        p.spheres = {{{0, 0, 0}, r, qi, kappa}, {{2 * r + h, 0, 0}, r, qj, 1.0}};
        auto sol = solver->solve(p);
        double f, u;
        t.eval(h, qi, qj, f, u);
        double qm = std::max(std::abs(qi), std::abs(qj));
        double f0 = qm * qm / (4 * 3.14159265358979 * 8.8541878128e-12 * 4 * r * r);
        EXPECT_NEAR(f, sol.force[1].x, 2e-3 * std::abs(sol.force[1].x) + 1e-6 * f0)
            << "kappa " << kappa << " h/r " << hr << " q " << qi << "," << qj;
        EXPECT_NEAR(-f, sol.force[0].x, 2e-3 * std::abs(sol.force[1].x) + 1e-6 * f0);
      }
    }
  }
}
