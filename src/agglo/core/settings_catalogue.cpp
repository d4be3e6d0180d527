#include "agglo/core/settings_catalogue.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <mutex>
#include <utility>

#include <fmt/format.h>

#include "agglo/core/settings_acoustic.hpp"
#include "agglo/core/settings_calibrate.hpp"
#include "agglo/core/settings_electrostatics.hpp"
#include "agglo/core/settings_impact.hpp"
#include "agglo/core/settings_outcomes.hpp"

namespace agglo::settings {

const ImpactSettings& impact_settings() {
  static const ImpactSettings s;
  return s;
}

const ElectrostaticsSettings& electrostatics_settings() {
  static const ElectrostaticsSettings s;
  return s;
}

const CalibrateSettings& calibrate_settings() {
  static const CalibrateSettings s;
  return s;
}

const OutcomesSettings& outcomes_settings() {
  static const OutcomesSettings s;
  return s;
}

const AcousticSettings& acoustic_settings() {
  static const AcousticSettings s;
  return s;
}

namespace {

std::array<std::string, 12> builder_text(std::string_view table, std::string_view what) {
  auto key = [&](std::string_view leaf) { return fmt::format("{}.{}", table, leaf); };
  return {key("seed"),
          fmt::format("random seed of the generated {} (shape fractal, bpca, bcca)", what),
          key("primaries"),
          "number of primaries N of shape fractal, bpca, bcca",
          key("fractal_dimension"),
          "fractal dimension D_f of shape fractal",
          key("fractal_prefactor"),
          "fractal prefactor k_f of shape fractal",
          key("radius_std"),
          "geometric standard deviation sigma_g of the lognormal primary radii (fractal, bpca, bcca)",
          key("file"),
          "CSV of shape file: header with x, y, z, radius [m], optional charge [C], permittivity, material; "
          "relative paths from the case file's folder"};
}

}  // namespace

BuilderKeys::BuilderKeys(Table& t, std::string_view table, std::string_view what)
    : text_(builder_text(table, what)),
      seed{t, {text_[0], "", text_[1]}, 1, 0, INT64_MAX},
      primaries{t, {text_[2], "", text_[3]}, 64, 2, 10000},
      fractal_dimension{t, {text_[4], "", text_[5]}, 1.8, Range::closed(1.0, 3.0)},
      fractal_prefactor{t, {text_[6], "", text_[7]}, 1.3, Range::open_closed(0.0, 100.0)},
      radius_std{t, {text_[8], "", text_[9], {}, "1 = monodisperse"}, 1.0, Range::closed(1.0, 3.0)},
      file{t, {text_[10], "", text_[11]}, std::nullopt} {}

std::vector<const Table*> ImpactSettings::tables() const {
  return {&top.t, &material.t, &materials.t, &time.t, &agglomerate.t, &projectile.t, &output.t, &vcrit.t, &breakup.t, &wall.t};
}

std::vector<const Table*> AcousticSettings::tables() const {
  return {&top.t,      &gas.t,    &sound.t,   &time.t,     &population.t, &sampling.t,
          &domain.t,   &outcomes.t, &output.t,   &sectional.t};
}

namespace {

struct Added {
  std::mutex mutex;
  std::vector<std::pair<const Table*, const Table*>> tables;  // (table, listed after)
};

Added& added() {
  static Added a;
  return a;
}

}  // namespace

bool add_table(const Table& table, const Table& after) {
  auto& a = added();
  std::lock_guard lock(a.mutex);
  a.tables.emplace_back(&table, &after);
  return true;
}

std::vector<const Table*> all_tables() {
  std::vector<const Table*> core;
  for (const auto& part : {impact_settings().tables(), electrostatics_settings().tables(), acoustic_settings().tables(),
                           calibrate_settings().tables(), outcomes_settings().tables()})
    core.insert(core.end(), part.begin(), part.end());
  auto& a = added();
  std::lock_guard lock(a.mutex);
  std::vector<const Table*> out;
  for (const Table* t : core) {
    out.push_back(t);
    for (const auto& [table, after] : a.tables)
      if (after == t) out.push_back(table);
  }
  return out;
}

namespace {

using Row = std::array<std::string, 6>;

Row row_of(const Setting& s) {
  return {std::string(s.dotted()), std::string(type_name(s.type())), std::string(s.info().unit), s.default_text(),
          s.range_text(), std::string(s.info().meaning)};
}

std::string heading(const Table& t) {
  if (t.name().empty()) return "top level";
  return t.array() ? fmt::format("[[{}]]", t.name()) : fmt::format("[{}]", t.name());
}

bool selected(const Table& t, std::string_view section) {
  return section.empty() || t.name() == section || (t.name().empty() && section == "top");
}

std::string aligned(const Table& t) {
  std::vector<Row> rows = {{"key", "type", "unit", "default", "range", "meaning"}};
  for (const auto* s : t.settings()) rows.push_back(row_of(*s));
  std::array<std::size_t, 6> w{};
  for (const auto& r : rows)
    for (std::size_t c = 0; c < w.size(); ++c) w[c] = std::max(w[c], r[c].size());
  std::string out = fmt::format("{} ({}): {}\n", heading(t), t.commands(), t.title());
  for (const auto& r : rows) {
    std::string line;
    for (std::size_t c = 0; c + 1 < w.size(); ++c) line += fmt::format("{:<{}}  ", r[c].empty() ? "-" : r[c], w[c]);
    out += "  " + line + r[5] + "\n";
  }
  return out;
}

}  // namespace

std::string list_text(std::string_view section) {
  std::string out;
  for (const auto* t : all_tables())
    if (selected(*t, section)) {
      if (!out.empty()) out += '\n';
      out += aligned(*t);
    }
  if (out.empty())
    throw ConfigError(fmt::format("config --list '{}': no such section (see agglo config --list)", section));
  return out;
}

std::string markdown_text() {
  std::string out =
      "# Case-file settings\n\n"
      "Generated by `agglo config --markdown` from the settings tables (src/agglo/core/settings_*.hpp, and\n"
      "src/agglo/dem/contact/settings.hpp, src/agglo/acoustics/kernels/keys.hpp beside the models they name);\n"
      "do not edit by hand (a test fails when this file is stale). Every key of a case file is listed\n"
      "once, with its unit, its default (written into config.resolved.toml when the key is absent)\n"
      "and its allowed range; \"required\" keys have no default.\n";
  for (const auto* t : all_tables()) {
    std::string title(t->title());
    title[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(title[0])));
    out += fmt::format("\n## {}\n\n{}. Read by: {}.\n\n", heading(*t), title, t->commands());
    out += "| key | type | unit | default | range | meaning |\n|---|---|---|---|---|---|\n";
    for (const auto* s : t->settings()) {
      Row r = row_of(*s);
      out += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", r[0], r[1], r[2], r[3], r[4], r[5]);
    }
  }
  return out;
}

}  // namespace agglo::settings
