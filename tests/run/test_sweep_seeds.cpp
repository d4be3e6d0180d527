// Sweeps with seeds (run/seed_ensemble.hpp, run/ensemble_request.hpp): the seed axis (member seeds of the base seed, appended last;
// refusals), the grouping of the runs into points and their statistics against the formula of
// io/ensemble_stats.hpp. The whole command is tested end to end by tests/cli/sweep_seeds.sh.
#include <gtest/gtest.h>

#include <cmath>

#include "agglo/core/error.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/run/seed_ensemble.hpp"

using namespace agglo;
using namespace agglo::run;

namespace {

Config baseline() { return Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/seed002_baseline.toml"); }

}  // namespace

TEST(SweepSeeds, SeedAxisIsAppendedWithTheMemberSeedsOfTheBaseSeed) {
  const auto& cmd = find_command("acoustic");
  const Config base = baseline();
  const auto axes = with_seed_axis(cmd, base, {{"population.1.diameter", {"1e-5", "2e-5"}}}, 4);
  ASSERT_EQ(axes.size(), 2u);
  EXPECT_EQ(axes[0].key, "population.1.diameter");
  EXPECT_EQ(axes[1].key, cmd.seed_key()->dotted());
  const auto seeds = member_seeds(cmd.seed(base), 4);
  ASSERT_EQ(axes[1].values.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(axes[1].values[k], std::to_string(seeds[k]));
  EXPECT_EQ(axes[1].values[0], std::to_string(cmd.seed(base)));  // member 0: the case's own seed
}

TEST(SweepSeeds, RefusesTooFewMembersASweptSeedAndCommandsWithoutSeed) {
  const auto& acoustic = find_command("acoustic");
  const Config base = baseline();
  const std::vector<SweepAxis> axes{{"population.1.diameter", {"1e-5"}}};
  EXPECT_THROW(with_seed_axis(acoustic, base, axes, 1), ConfigError);
  EXPECT_THROW(with_seed_axis(acoustic, base, axes, -3), ConfigError);
  EXPECT_THROW(with_seed_axis(acoustic, base, {{std::string(acoustic.seed_key()->dotted()), {"1", "2"}}}, 2),
               ConfigError);
  EXPECT_THROW(with_seed_axis(find_command("collide"), base, axes, 2), ConfigError);
}

TEST(SweepSeeds, PointsGroupConsecutiveRunsAndAverageThem) {
  SweepResult res;  // 2 points x 3 members, the seed the last (fastest) axis
  const double x[6] = {0.1, 0.4, 0.7, 2.0, 2.0, 5.0};
  for (std::size_t i = 0; i < 6; ++i) {
    res.cases.push_back({i, {i < 3 ? "a" : "b", std::to_string(i % 3)}, {}, "case_" + std::to_string(i)});
    res.summaries.push_back({{"eff", x[i]}, {"nested", {{"n", static_cast<double>(i)}}}});
  }
  const auto points = sweep_points(res, 3);
  ASSERT_EQ(points.size(), 2u);
  for (std::size_t p = 0; p < 2; ++p) {
    EXPECT_EQ(points[p].values, std::vector<std::string>{p == 0 ? "a" : "b"});  // the seed dropped
    EXPECT_EQ(points[p].folder, "case_" + std::to_string(3 * p));              // member 0's folder
    EXPECT_EQ(points[p].members, 3u);
    ASSERT_EQ(points[p].stats.size(), 2u);
    EXPECT_EQ(points[p].stats[1].quantity, "nested.n");
    const double* v = x + 3 * p;
    const double m = (v[0] + v[1] + v[2]) / 3.0;
    const double s = std::sqrt(((v[0] - m) * (v[0] - m) + (v[1] - m) * (v[1] - m) + (v[2] - m) * (v[2] - m)) / 6.0);
    EXPECT_NEAR(points[p].stats[0].value.mean, m, 1e-15 * std::abs(m));
    EXPECT_NEAR(points[p].stats[0].value.standard_error, s, 1e-15 * s);
    EXPECT_EQ(points[p].stats[0].value.n, 3u);
  }
}
