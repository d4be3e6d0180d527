#include "agglo/core/settings.hpp"

#include <fmt/format.h>

namespace agglo::settings {

namespace {

std::string real_text(double v) { return fmt::format("{:g}", v); }

std::string list_text(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + real_text(v[k]);
  return s + "]";
}

Range with_unit(Range r, std::string unit) {
  r.unit = std::move(unit);
  return r;
}

std::string bounds_text(Range r) {
  r.unit.clear();
  return r.describe();
}

}  // namespace

std::string_view type_name(Type t) {
  switch (t) {
    case Type::real: return "real";
    case Type::integer: return "integer";
    case Type::boolean: return "bool";
    case Type::text: return "string";
    case Type::choice: return "choice";
    case Type::reals: return "real list";
    case Type::vec3: return "vec3";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------------
Table::Table(std::string_view name, std::string_view commands, std::string_view title, bool array)
    : name_(name), commands_(commands), title_(title), array_(array) {}

ConfigSection Table::open(const ConfigSection& root) const { return name_.empty() ? root : root.section(name_); }

std::vector<ConfigSection> Table::elements(const ConfigSection& root) const { return root.tables(name_); }

bool Table::present(const ConfigSection& root) const { return root.has(name_); }

void Table::fail(const ConfigSection& root, std::string_view rule) const { root.fail(name_, rule); }

// ---------------------------------------------------------------------------------------------
Setting::Setting(Table& table, const Info& info, Type type) : table_(&table), info_(info), type_(type) {
  table.settings_.push_back(this);
}

std::string_view Setting::leaf() const {
  const auto n = table_->name().size();
  return n == 0 ? info_.key : info_.key.substr(n + 1);
}

void Setting::reject(const ConfigSection& section, std::string_view rule) const { section.fail_value(leaf(), rule); }

void Setting::missing(const ConfigSection& section, std::string_view rule) const { section.fail(leaf(), rule); }

bool Setting::present(const ConfigSection& section) const { return section.has(leaf()); }

std::string Setting::unit_text() const {
  std::string u(info_.unit);
  if (!info_.range_note.empty()) u += (u.empty() ? "(" : " (") + std::string(info_.range_note) + ")";
  return u;
}

std::string Setting::note_or(std::string text) const {
  return info_.default_note.empty() ? text : std::string(info_.default_note);
}

// ---------------------------------------------------------------------------------------------
Real::Real(Table& t, const Info& i, std::optional<double> def, Range range)
    : Setting(t, i, Type::real), def_(def), range_(with_unit(range, unit_text())) {}

double Real::read_or(const ConfigSection& s, std::optional<double> def) const { return s.number(leaf(), def, range_); }

std::string Real::default_text() const { return note_or(def_ ? real_text(*def_) : "required"); }

std::string Real::range_text() const {
  const auto note = info().range_note;
  return note.empty() ? bounds_text(range_) : fmt::format("{} ({})", bounds_text(range_), note);
}

Integer::Integer(Table& t, const Info& i, std::optional<std::int64_t> def, std::int64_t lo, std::int64_t hi)
    : Setting(t, i, Type::integer), def_(def), lo_(lo), hi_(hi) {}

std::int64_t Integer::read(const ConfigSection& s) const { return s.integer(leaf(), def_, lo_, hi_); }

std::string Integer::default_text() const { return note_or(def_ ? std::to_string(*def_) : "required"); }

std::string Integer::range_text() const { return fmt::format("[{}, {}]", lo_, hi_); }

Bool::Bool(Table& t, const Info& i, std::optional<bool> def) : Setting(t, i, Type::boolean), def_(def) {}

bool Bool::read(const ConfigSection& s) const { return s.boolean(leaf(), def_); }

std::string Bool::default_text() const { return note_or(def_ ? (*def_ ? "true" : "false") : "required"); }

Text::Text(Table& t, const Info& i, std::optional<std::string_view> def) : Setting(t, i, Type::text), def_(def) {}

std::string Text::read(const ConfigSection& s) const {
  return s.string(leaf(), def_ ? std::optional<std::string>(std::string(*def_)) : std::nullopt);
}

std::string Text::default_text() const { return note_or(def_ ? fmt::format("\"{}\"", *def_) : "required"); }

Choice::Choice(Table& t, const Info& i, std::optional<std::string_view> def, std::vector<std::string_view> allowed)
    : Setting(t, i, Type::choice), def_(def), fixed_(std::move(allowed)) {}

Choice::Choice(Table& t, const Info& i, std::optional<std::string_view> def, NameSource names, Legacy legacy)
    : Setting(t, i, Type::choice), def_(def), source_(names), legacy_(std::move(legacy)) {}

std::vector<std::string> Choice::allowed() const {
  if (source_) return source_();
  return {fixed_.begin(), fixed_.end()};
}

std::string Choice::read_or(const ConfigSection& s, std::optional<std::string_view> def) const {
  if (!legacy_.if_true.empty())
    if (const auto b = s.boolean_if_set(leaf())) return std::string(*b ? legacy_.if_true : legacy_.if_false);
  if (const auto v = s.string_if_set(leaf()))
    for (const auto& [old_name, new_name] : legacy_.renamed)
      if (*v == old_name) {
        s.warn(leaf(), fmt::format("\"{}\" is deprecated, read as \"{}\" (its new name)", old_name, new_name));
        return std::string(new_name);
      }
  const std::vector<std::string> names = allowed();
  const std::vector<std::string_view> views(names.begin(), names.end());
  return s.choice(leaf(), def ? std::optional<std::string>(std::string(*def)) : std::nullopt, views);
}

std::string Choice::default_text() const { return note_or(def_ ? fmt::format("\"{}\"", *def_) : "required"); }

std::string Choice::range_text() const {
  std::string s;
  for (const auto& a : allowed()) s += (s.empty() ? "\"" : ", \"") + a + "\"";
  if (!legacy_.if_true.empty())
    s += fmt::format(" (also true = \"{}\", false = \"{}\")", legacy_.if_true, legacy_.if_false);
  for (const auto& [old_name, new_name] : legacy_.renamed)
    s += fmt::format(" (\"{}\": deprecated name of \"{}\")", old_name, new_name);
  return s;
}

Reals::Reals(Table& t, const Info& i, std::optional<std::vector<double>> def, Range range)
    : Setting(t, i, Type::reals), def_(std::move(def)), range_(with_unit(range, unit_text())) {}

std::vector<double> Reals::read_or(const ConfigSection& s, std::optional<std::vector<double>> def,
                                   std::optional<Range> range) const {
  return s.numbers(leaf(), std::move(def), range ? with_unit(*range, unit_text()) : range_);
}

std::string Reals::default_text() const { return note_or(def_ ? list_text(*def_) : "required"); }

std::string Reals::range_text() const { return bounds_text(range_); }

Vector3::Vector3(Table& t, const Info& i, std::optional<Vec3> def, Range component_range)
    : Setting(t, i, Type::vec3), def_(def), range_(with_unit(component_range, unit_text())) {}

Vec3 Vector3::read(const ConfigSection& s) const { return s.vec3(leaf(), def_, range_); }

std::string Vector3::default_text() const {
  return note_or(def_ ? list_text({def_->x, def_->y, def_->z}) : "required");
}

std::string Vector3::range_text() const { return bounds_text(range_); }

}  // namespace agglo::settings
