// The fractal law an aggregate outcome table records (impact/outcome_fractal_law.hpp): the requested D_f, k_f
// of fractal partners; for BPCA partners the fit of ln(R_g/a) against ln N over the structures of the grid's
// impacts (checked against the fit of the structures outcome_case builds); none with one size.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/impact/outcome_aggregates.hpp"
#include "agglo/impact/outcome_fractal_law.hpp"
#include "agglo/structure/observables.hpp"

using namespace agglo;
using namespace agglo::impact;

namespace {

struct LawParsed {
  ImpactCase dem;
  OutcomeGridSpec grid;
};
LawParsed parse_law_case(const std::string& shape, const std::string& grid) {
  const std::string law = shape == "fractal" ? "fractal_dimension = 1.8\nfractal_prefactor = 1.3\n" : "";
  Config cfg = Config::from_string(R"(
[material]
density = 2500.0
[agglomerate]
shape = ")" + shape + R"("
radius = 0.5e-6
)" + law + R"(
[projectile]
shape = ")" + shape + R"("
)" + law + R"(
[outcome_grid]
speeds = [1.0, 3.0]
)" + grid,
                                   "law.toml");
  LawParsed p{parse_impact_case(cfg, true), parse_outcome_grid(cfg.root())};
  check_aggregate_pair(cfg.root(), p.dem, p.grid);
  return p;
}

}  // namespace

TEST(OutcomeFractalLaw, RequestedForFractalPartnersFittedForBallistic) {
  const LawParsed f = parse_law_case("fractal", "primaries = [8, 16]\nimpacts = 1\n");
  const TableFractalLaw requested = table_fractal_law(f.dem, f.grid);
  ASSERT_TRUE(requested.known);
  EXPECT_EQ(requested.fractal_dimension, 1.8);
  EXPECT_EQ(requested.fractal_prefactor, 1.3);
  EXPECT_EQ(requested.how.rfind("requested", 0), 0u) << requested.how;

  const LawParsed b = parse_law_case("bpca", "primaries = [2, 4, 8]\nimpacts = 2\n");
  const TableFractalLaw fit = table_fractal_law(b.dem, b.grid);
  ASSERT_TRUE(fit.known);
  // independently: every structure of the first speed's impacts (both partners), fitted
  std::vector<double> n, rg;
  for (const auto& j : outcome_impacts(b.grid)) {
    if (j.iv != 0) continue;
    const ImpactCase c = outcome_case(b.dem, b.grid, j);
    for (const auto* a : {&c.agglomerate, &c.projectile.body}) {
      n.push_back(static_cast<double>(a->structure.size()));
      rg.push_back(structure::rg_point_mass(a->structure) / 0.5e-6);
    }
  }
  ASSERT_EQ(n.size(), 2u * 6u * 2u);  // 6 size pairs x 2 samples x 2 partners
  const auto ref = structure::fit_fractal(n, rg);
  EXPECT_DOUBLE_EQ(fit.fractal_dimension, ref.fractal_dimension);
  EXPECT_DOUBLE_EQ(fit.fractal_prefactor, ref.fractal_prefactor);
  EXPECT_GT(fit.fractal_dimension, 1.0);
  EXPECT_LT(fit.fractal_dimension, 3.0);
  EXPECT_NE(fit.fractal_dimension, 1.8);  // not the (unused) requested keys of the case
  EXPECT_EQ(fit.how.rfind("fit", 0), 0u) << fit.how;

  const LawParsed one = parse_law_case("bpca", "primaries = [4]\nimpacts = 2\n");
  EXPECT_FALSE(table_fractal_law(one.dem, one.grid).known);  // one size: no fit
}
