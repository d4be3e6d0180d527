#pragma once
// Declared settings: every case-file key is declared exactly once, as a setting object in a
// settings table (one table per section, see settings_*.hpp), with its type, unit, default (or
// "required"), allowed range and a one-line meaning. Parsers read values through these objects
// (never through a second copy of the key string), cross-key rules name the other key through its
// object, and `agglo config --list / --markdown` print the same tables (docs/config.md).
//
// Reading goes through ConfigSection, so a missing key gets its default written into the case
// table (config.resolved.toml) and every error is one line "<file>: key '<dotted.key>' = <value>:
// <rule>". A default that depends on other values (e.g. the projectile radius defaults to the
// agglomerate radius) is passed at the read (`read_or`) and documented by `default_note`.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "agglo/core/config.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/vec3.hpp"

namespace agglo::settings {

enum class Type { real, integer, boolean, text, choice, reals, vec3 };
std::string_view type_name(Type t);

class Setting;

// One section of the case file ([name], [[name]] when `array`, or the top level when name is "").
class Table {
 public:
  Table(std::string_view name, std::string_view commands, std::string_view title, bool array = false);
  Table(const Table&) = delete;
  Table& operator=(const Table&) = delete;

  std::string_view name() const { return name_; }
  std::string_view commands() const { return commands_; }  // the commands that read it
  std::string_view title() const { return title_; }
  bool array() const { return array_; }
  const std::vector<const Setting*>& settings() const { return settings_; }

  // The section (created if absent, so that defaults land in the resolved config); the root for "".
  ConfigSection open(const ConfigSection& root) const;
  // The elements of an array of tables ([[name]]); empty if absent.
  std::vector<ConfigSection> elements(const ConfigSection& root) const;
  bool present(const ConfigSection& root) const;
  // One-line error about the whole section (e.g. "at least one [[population]] table is required").
  [[noreturn]] void fail(const ConfigSection& root, std::string_view rule) const;

 private:
  friend class Setting;
  std::string_view name_, commands_, title_;
  bool array_;
  std::vector<const Setting*> settings_;
};

// Descriptive part of a declaration: dotted key ("material.restitution"; elements of [[particles]]:
// "particles.radius"), unit, meaning, the text of a computed default and a note on the range.
struct Info {
  std::string_view key;
  std::string_view unit;
  std::string_view meaning;
  std::string_view default_note = {};  // documents a default computed at the read (read_or)
  std::string_view range_note = {};    // e.g. "0 = automatic", shown after the unit in messages
};

class Setting {
 public:
  Setting(Table& table, const Info& info, Type type);
  Setting(const Setting&) = delete;
  Setting& operator=(const Setting&) = delete;
  virtual ~Setting() = default;

  std::string_view dotted() const { return info_.key; }
  std::string_view leaf() const;  // key inside its section
  const Table& table() const { return *table_; }
  Type type() const { return type_; }
  const Info& info() const { return info_; }

  virtual std::string default_text() const = 0;  // "2500", "\"seed\"", "required", or the note
  virtual std::string range_text() const = 0;    // "(0, inf)", "[3, 1000]", "\"a\", \"b\"", ""

  // One-line errors naming this key in `section` (the value is shown by reject).
  [[noreturn]] void reject(const ConfigSection& section, std::string_view rule) const;
  [[noreturn]] void missing(const ConfigSection& section, std::string_view rule) const;
  bool present(const ConfigSection& section) const;

 protected:
  std::string unit_text() const;  // unit plus range note, as used in range messages
  std::string note_or(std::string text) const;

 private:
  const Table* table_;
  Info info_;
  Type type_;
};

class Real : public Setting {
 public:
  Real(Table& t, const Info& i, std::optional<double> def, Range range);
  double read(const ConfigSection& s) const { return read_or(s, def_); }
  double read_or(const ConfigSection& s, std::optional<double> def) const;
  double def() const { return *def_; }
  const Range& range() const { return range_; }  // for values given outside a case file (Python arrays)
  std::string default_text() const override;
  std::string range_text() const override;

 private:
  std::optional<double> def_;
  Range range_;
};

class Integer : public Setting {
 public:
  Integer(Table& t, const Info& i, std::optional<std::int64_t> def, std::int64_t lo, std::int64_t hi);
  std::int64_t read(const ConfigSection& s) const;
  std::int64_t def() const { return *def_; }
  std::string default_text() const override;
  std::string range_text() const override;

 private:
  std::optional<std::int64_t> def_;
  std::int64_t lo_, hi_;
};

class Bool : public Setting {
 public:
  Bool(Table& t, const Info& i, std::optional<bool> def);
  bool read(const ConfigSection& s) const;
  bool def() const { return *def_; }
  std::string default_text() const override;
  std::string range_text() const override { return ""; }

 private:
  std::optional<bool> def_;
};

class Text : public Setting {
 public:
  Text(Table& t, const Info& i, std::optional<std::string_view> def);
  std::string read(const ConfigSection& s) const;
  std::string_view def() const { return *def_; }
  std::string default_text() const override;
  std::string range_text() const override { return ""; }

 private:
  std::optional<std::string_view> def_;
};

// The allowed values of a Choice computed when they are needed: the names a registry of sub-models
// holds (dem/contact/registry.hpp, acoustics/kernels/registry.hpp), so that they are declared once.
using NameSource = std::vector<std::string> (*)();

// Former values a Choice still accepts. `if_true`/`if_false`: a boolean, from the time the key was a
// switch, means that name (no warning). `renamed`: a deprecated value, read as its new name with a
// one-line warning (Config::take_warnings()).
struct Legacy {
  std::string_view if_true = {}, if_false = {};
  std::vector<std::pair<std::string_view, std::string_view>> renamed = {};  // old value -> new value
};

class Choice : public Setting {
 public:
  Choice(Table& t, const Info& i, std::optional<std::string_view> def, std::vector<std::string_view> allowed);
  Choice(Table& t, const Info& i, std::optional<std::string_view> def, NameSource names, Legacy legacy = {});
  std::string read(const ConfigSection& s) const { return read_or(s, def_); }
  std::string read_or(const ConfigSection& s, std::optional<std::string_view> def) const;
  std::string_view def() const { return *def_; }
  std::vector<std::string> allowed() const;
  std::string default_text() const override;
  std::string range_text() const override;

 private:
  std::optional<std::string_view> def_;
  std::vector<std::string_view> fixed_;
  NameSource source_ = nullptr;
  Legacy legacy_;
};

class Reals : public Setting {
 public:
  Reals(Table& t, const Info& i, std::optional<std::vector<double>> def, Range range);
  std::vector<double> read(const ConfigSection& s) const { return read_or(s, def_); }
  // `range` replaces the declared one when the bounds depend on other values (e.g. the run end).
  std::vector<double> read_or(const ConfigSection& s, std::optional<std::vector<double>> def,
                              std::optional<Range> range = std::nullopt) const;
  std::string default_text() const override;
  std::string range_text() const override;

 private:
  std::optional<std::vector<double>> def_;
  Range range_;
};

class Vector3 : public Setting {
 public:
  Vector3(Table& t, const Info& i, std::optional<Vec3> def, Range component_range);
  Vec3 read(const ConfigSection& s) const;
  const Range& component_range() const { return range_; }
  std::string default_text() const override;
  std::string range_text() const override;

 private:
  std::optional<Vec3> def_;
  Range range_;
};

// "Engines throw errors about physics, the config layer maps them to keys": runs a model's own
// check and turns the agglo::NumericalError (or std::invalid_argument) it throws into a one-line
// ConfigError naming `target` (a Setting in `section`, or a whole Table under the root `section`).
inline void fail_on(const Setting& s, const ConfigSection& section, std::string_view rule) { s.reject(section, rule); }
inline void fail_on(const Table& t, const ConfigSection& root, std::string_view rule) { t.fail(root, rule); }

template <class Target, class Check>
void check_as(const Target& target, const ConfigSection& section, Check&& check) {
  try {
    check();
  } catch (const NumericalError& e) {
    fail_on(target, section, e.what());
  } catch (const std::invalid_argument& e) {
    fail_on(target, section, e.what());
  }
}

}  // namespace agglo::settings
