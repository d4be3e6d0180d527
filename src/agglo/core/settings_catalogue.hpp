#pragma once
// All settings tables of agglo, and their listings: `agglo config --list [section]` (plain text) and
// `agglo config --markdown` (docs/config.md).
#include <string>
#include <string_view>
#include <vector>

#include "agglo/core/settings.hpp"

namespace agglo::settings {

// Every table, in documentation order (impact, electrostatics, acoustic, calibrate).
std::vector<const Table*> all_tables();

// One line per key: key, type, unit, default, range, meaning (tab-separated), under a header line
// "[section] (commands): title" per table. `section` selects tables by name ("" = all; "top" = the
// top-level keys). Throws ConfigError for an unknown section.
std::string list_text(std::string_view section = "");

// docs/config.md: one Markdown table per section.
std::string markdown_text();

}  // namespace agglo::settings
