// Sectional case files: what the solver cannot do is a ConfigError naming the key; the outputs follow the
// acoustic run's conventions (efficiency rows, psd.csv normalisation).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "agglo/core/error.hpp"
#include "agglo/sectional/run.hpp"
#include "helpers.hpp"

using namespace agglo::sectional;

namespace {
std::string config_error(const std::vector<std::string>& overrides) {
  try {
    (void)test::shipped_case("partmc_brownian", overrides);
  } catch (const agglo::ConfigError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(SectionalCase, UnsupportedSettingsNameTheirKey) {
  EXPECT_NE(config_error({"kernels.model=\"acoustic\""}).find("kernels.model"), std::string::npos);
  EXPECT_NE(config_error({"outcomes.always_coalesce=false"}).find("outcomes.always_coalesce"), std::string::npos);
  EXPECT_NE(config_error({"kernels.exclude_same_population=true"}).find("kernels.exclude_same_population"),
            std::string::npos);
  EXPECT_NE(config_error({"sectional.d_max=1e-10"}).find("sectional.d_max"), std::string::npos);
  EXPECT_NE(config_error({"sectional.bins_per_decade=2"}).find("sectional.bins_per_decade"), std::string::npos);
  EXPECT_EQ(config_error({}), "");
}

TEST(SectionalCase, ObservationsLikeAnAcousticRun) {
  const auto c = test::shipped_case("partmc_constant");
  const auto obs = run_sectional(c);
  ASSERT_EQ(obs.efficiency.size(), 101u);  // every 0.18 s over 18 s
  EXPECT_DOUBLE_EQ(obs.efficiency.back().t, 18.0);
  EXPECT_NEAR(obs.efficiency.back().counts.n_total / 4.8e10, 0.1, 1e-4);
  EXPECT_EQ(obs.efficiency.back().counts.n_phase[1], obs.efficiency.back().counts.n_total);  // liquid case
  ASSERT_EQ(obs.psd.size(), 4u);
  // psd.csv: the integral of dN/dlog10 d over the output bins is the number within them (all of it here).
  const auto& e = obs.bins.edges;
  for (const auto& rec : obs.psd) {
    double n = 0.0;
    for (std::size_t b = 0; b + 1 < e.size(); ++b) n += rec.dndlogd[3][b] * std::log10(e[b + 1] / e[b]);
    const auto& row = *std::find_if(obs.efficiency.begin(), obs.efficiency.end(),
                                    [&](const auto& r) { return std::abs(r.t - rec.t) < 1e-9; });
    EXPECT_NEAR(n, row.counts.n_total, 2e-3 * row.counts.n_total) << "t = " << rec.t;
  }
}
