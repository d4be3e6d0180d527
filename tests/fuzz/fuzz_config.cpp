// libFuzzer target of the case-file parser and of every command's validation (docs/fuzzing.md).
// Input: TOML text, optionally followed by a line "--set" and one override per line. The text is
// parsed, the overrides applied, then each command parses and validates its own copy and the
// resolved table is printed. ConfigError is the only allowed failure: any other exception, a crash,
// a leak or undefined behaviour (AddressSanitizer, UndefinedBehaviorSanitizer) is a finding.
// Built only with -DAGGLO_FUZZ=ON and clang (tests/fuzz/CMakeLists.txt).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "agglo/core/config.hpp"
#include "agglo/core/error.hpp"
#include "agglo/run/commands.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  std::string sets;
  const std::string marker = "\n--set\n";
  if (const auto cut = text.find(marker); cut != std::string::npos) {
    sets = text.substr(cut + marker.size());
    text.resize(cut);
  }
  try {
    agglo::Config cfg = agglo::Config::from_string(text, "fuzz.toml");
    std::istringstream lines(sets);
    for (std::string line; std::getline(lines, line);) cfg.apply_override(line);
    for (const auto* cmd : agglo::run::all_commands()) {
      agglo::Config copy = cfg.clone();
      try {
        cmd->parse(copy);
        (void)copy.resolved_toml();
      } catch (const agglo::ConfigError&) {
      }
    }
  } catch (const agglo::ConfigError&) {
  }
  return 0;
}
