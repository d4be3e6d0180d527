#pragma once
// Shared helpers of the acoustics tests: build an engine from an inline TOML case.
#include <string>

#include "agglo/acoustics/case_config.hpp"
#include "agglo/acoustics/engine.hpp"
#include "agglo/core/config.hpp"

namespace agglo::acoustics::test {

inline AcousticCase parse_case(const std::string& toml) {
  Config cfg = Config::from_string(toml, "test.toml");
  return parse_acoustic_case(cfg);
}

inline Engine make_engine(const std::string& toml) { return Engine(parse_case(toml).engine); }

}  // namespace agglo::acoustics::test
