#pragma once
// Shared helpers of the sectional tests: a shipped case (cases/<stem>.toml) with overrides, solved.
#include <cmath>
#include <string>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/sectional/case_config.hpp"
#include "agglo/sectional/solver.hpp"

namespace agglo::sectional::test {

inline SectionalCase shipped_case(const std::string& stem, const std::vector<std::string>& overrides = {}) {
  Config cfg = Config::load(std::string(AGGLO_SOURCE_DIR) + "/cases/" + stem + ".toml");
  for (const auto& o : overrides) cfg.apply_override(o);
  return parse_sectional_case(cfg);
}

// Relative L2 distance ||a - b|| / ||b|| of two pivot vectors, optionally weighted (e.g. by volume).
inline double relative_l2(const std::vector<double>& a, const std::vector<double>& b,
                          const std::vector<double>& w = {}) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double wi = w.empty() ? 1.0 : w[i];
    num += (wi * (a[i] - b[i])) * (wi * (a[i] - b[i]));
    den += (wi * b[i]) * (wi * b[i]);
  }
  return std::sqrt(num / den);
}

}  // namespace agglo::sectional::test
