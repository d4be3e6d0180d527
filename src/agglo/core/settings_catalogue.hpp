#pragma once
// All settings tables of agglo, and their listings: `agglo config --list [section]` (plain text) and
// `agglo config --markdown` (docs/config.md).
#include <string>
#include <string_view>
#include <vector>

#include "agglo/core/settings.hpp"

namespace agglo::settings {

// Every table, in documentation order (impact, electrostatics, acoustic, calibrate). The tables
// declared in this folder are always listed; a table declared by an engine next to the models it
// names (dem/contact/settings.hpp [contact], acoustics/kernels/settings.hpp [kernels]) is listed once
// its owner has built it, which run::all_commands() makes sure of.
std::vector<const Table*> all_tables();

// Lists an engine's table right after `after`; returns true.
bool add_table(const Table& table, const Table& after);

// One line per key: key, type, unit, default, range, meaning (tab-separated), under a header line
// "[section] (commands): title" per table. `section` selects tables by name ("" = all; "top" = the
// top-level keys). Throws ConfigError for an unknown section.
std::string list_text(std::string_view section = "");

// docs/config.md: one Markdown table per section.
std::string markdown_text();

}  // namespace agglo::settings
