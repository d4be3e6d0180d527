// The sectional solver on PartMC's Brownian benchmark (cases/partmc_brownian.toml) against PartMC 2.9.0's
// own sectional N(t) (tests/data/partmc/brown_sectional_N.csv, every 60 s for 4 h): within 1e-3 at every
// time; and converged: doubling the pivots changes N(t) by < 1e-3.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "helpers.hpp"

using namespace agglo::sectional;

namespace {

std::vector<std::pair<double, double>> partmc_sectional_n() {
  std::ifstream in(std::string(AGGLO_SOURCE_DIR) + "/tests/data/partmc/brown_sectional_N.csv");
  std::vector<std::pair<double, double>> rows;
  std::string line;
  std::getline(in, line);  // header time_s,N_m3,N_m3_800bins
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    double t = 0, n = 0;
    char comma = 0;
    if (ls >> t >> comma >> n) rows.emplace_back(t, n);
  }
  return rows;
}

}  // namespace

TEST(SectionalPartmc, BrownianNumberMatchesPartmcSectional) {
  const auto ref = partmc_sectional_n();
  ASSERT_EQ(ref.size(), 241u);
  SectionalSolver s(test::shipped_case("partmc_brownian"));
  double worst = 0.0;
  for (const auto& [t, n] : ref) {
    s.advance_to(t);
    worst = std::max(worst, std::abs(s.number() / n - 1.0));
  }
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(ref.back().second / ref.front().second, 0.2);  // the case does coagulate (N/N0 = 0.197)
  RecordProperty("max_rel_diff", std::to_string(worst));
}

TEST(SectionalPartmc, DoublingThePivotsChangesNumberByLessThan1e3) {
  SectionalSolver coarse(test::shipped_case("partmc_brownian"));
  SectionalSolver fine(test::shipped_case("partmc_brownian", {"sectional.bins_per_decade=80"}));
  ASSERT_GT(fine.grid().size(), 2 * coarse.grid().size() - 2);
  double worst = 0.0;
  for (double t = 1800.0; t <= 14400.0; t += 1800.0) {
    coarse.advance_to(t);
    fine.advance_to(t);
    worst = std::max(worst, std::abs(coarse.number() / fine.number() - 1.0));
  }
  EXPECT_LT(worst, 1e-3);
  RecordProperty("max_rel_change", std::to_string(worst));
}
