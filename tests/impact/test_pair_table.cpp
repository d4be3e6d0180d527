// The tabulated isolated-pair solutions agree with direct two-sphere solves between table nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

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

// The process-wide cache (pair_table()) keys on every solver setting: a table whose settings differ
// from another's in a single field is never shared with it, and gives the values of its own settings.
TEST(PairTable, CacheKeyCoversEverySolverSetting) {
  es::SolverOptions base;
  base.solver = "spectral";
  const double r = 10e-6;
  const PairKey key{r, r, 15.0, 15.0, 1.0};
  const double h_min = 0.05 * r, h_max = 5 * r;
  const auto t0 = pair_table(base, key, h_min, h_max);
  EXPECT_EQ(pair_table(base, key, h_min, h_max), t0);  // identical settings: one table

  std::vector<std::pair<std::string, es::SolverOptions>> variants;
  auto vary = [&](const std::string& field, auto change) {
    es::SolverOptions o = base;
    change(o);
    variants.emplace_back(field, o);
  };
  vary("solver", [](es::SolverOptions& o) { o.solver = "coulomb"; });
  vary("max_degree", [](es::SolverOptions& o) { o.max_degree = 6; });
  vary("target_accuracy", [](es::SolverOptions& o) { o.target_accuracy = 1e-5; });
  vary("max_degree_limit", [](es::SolverOptions& o) { o.max_degree_limit = 3; });
  vary("far_field", [](es::SolverOptions& o) { o.far_field = "fmm"; });
  vary("preconditioner", [](es::SolverOptions& o) { o.preconditioner = "coarse"; });
  vary("patches_per_sphere", [](es::SolverOptions& o) { o.patches_per_sphere = 500; });
  vary("tolerance", [](es::SolverOptions& o) { o.tolerance = 1e-3; });
  vary("max_iterations", [](es::SolverOptions& o) { o.max_iterations = 150; });
  vary("matvec", [](es::SolverOptions& o) { o.matvec = "direct"; });
  vary("fmm_order", [](es::SolverOptions& o) { o.fmm_order = 8; });
  vary("fmm_leaf_size", [](es::SolverOptions& o) { o.fmm_leaf_size = 32; });
  for (const auto& [field, o] : variants) {
    const auto t = pair_table(o, key, h_min, h_max);
    EXPECT_NE(t, t0) << "tables differing only in " << field << " are shared";
    EXPECT_EQ(pair_table(o, key, h_min, h_max), t) << field;
  }

  // Values: the degree cap 3 changes the force at a small gap by far more than the table's error, and
  // the cached table gives what a table built with these settings gives.
  es::SolverOptions capped = base;
  capped.max_degree_limit = 3;
  const PairTable own(capped, key, h_min, h_max, 97);
  const double h = 0.07 * r, qi = 1e-14, qj = -2e-14;
  double f_cached, u_cached, f_own, u_own, f_base, u_base;
  pair_table(capped, key, h_min, h_max)->eval(h, qi, qj, f_cached, u_cached);
  own.eval(h, qi, qj, f_own, u_own);
  t0->eval(h, qi, qj, f_base, u_base);
  EXPECT_EQ(f_cached, f_own);
  EXPECT_EQ(u_cached, u_own);
  EXPECT_GT(std::abs(f_own - f_base), 1e-2 * std::abs(f_base));
}
