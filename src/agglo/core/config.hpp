#pragma once
// Case-file access: TOML (toml++) -> validated values.
//
// A `Config` owns the parsed case table. Sections hand out typed, range-checked values; a value
// that is absent gets its documented default *written into the table*, so that `resolved_toml()`
// is the fully resolved configuration of the run. Every key that was read is recorded, and
// `check_unknown_keys()` rejects anything the engine never asked for (typos are errors).
// Every failure throws ConfigError with one line: "<file>: key '<dotted.key>' = <value>: <rule>".
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace toml {
inline namespace v3 {
class table;
class node;
}
}  // namespace toml

namespace agglo {

// Allowed interval of a real value, with its unit for messages.
struct Range {
  double lo = -1e308, hi = 1e308;
  bool lo_closed = true, hi_closed = true;
  std::string unit;

  static Range any(std::string unit = "") { return {-1e308, 1e308, true, true, std::move(unit)}; }
  static Range positive(std::string unit = "") { return {0.0, 1e308, false, true, std::move(unit)}; }
  static Range nonnegative(std::string unit = "") { return {0.0, 1e308, true, true, std::move(unit)}; }
  static Range closed(double a, double b, std::string unit = "") { return {a, b, true, true, std::move(unit)}; }
  static Range open_closed(double a, double b, std::string unit = "") { return {a, b, false, true, std::move(unit)}; }
  static Range closed_open(double a, double b, std::string unit = "") { return {a, b, true, false, std::move(unit)}; }
  static Range open(double a, double b, std::string unit = "") { return {a, b, false, false, std::move(unit)}; }
  bool contains(double v) const;
  std::string describe() const;
};

class Config;

class ConfigSection {
 public:
  // Dotted path of this section ("" for the root).
  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;
  bool has(std::string_view key) const;

  // Typed getters. `def` = nullopt makes the key required.
  double number(std::string_view key, std::optional<double> def, const Range& range) const;
  std::int64_t integer(std::string_view key, std::optional<std::int64_t> def, std::int64_t lo,
                       std::int64_t hi) const;
  bool boolean(std::string_view key, std::optional<bool> def) const;
  std::string string(std::string_view key, std::optional<std::string> def) const;
  std::string choice(std::string_view key, std::optional<std::string> def,
                     const std::vector<std::string_view>& allowed) const;
  Vec3 vec3(std::string_view key, std::optional<Vec3> def, const Range& component_range) const;
  std::vector<double> numbers(std::string_view key, std::optional<std::vector<double>> def,
                              const Range& range) const;
  // The value if it is set and has that type (the key counts as read), else nullopt.
  std::optional<bool> boolean_if_set(std::string_view key) const;
  std::optional<std::string> string_if_set(std::string_view key) const;

  // Sub-table (created if absent so defaults land in the resolved config).
  ConfigSection section(std::string_view key) const;
  // Array of tables ([[key]]); empty if absent.
  std::vector<ConfigSection> tables(std::string_view key) const;

  // Build the one-line error for this key.
  [[noreturn]] void fail(std::string_view key, std::string_view what) const;
  [[noreturn]] void fail_value(std::string_view key, std::string_view what) const;
  // A one-line warning "<file>: key '<dotted.key>' = <value>: <what>" kept by the Config (warnings()).
  void warn(std::string_view key, std::string_view what) const;

 private:
  friend class Config;
  ConfigSection(Config* cfg, toml::table* t, std::string path) : cfg_(cfg), tbl_(t), path_(std::move(path)) {}
  toml::node* lookup(std::string_view key) const;
  void mark(std::string_view key) const;
  Config* cfg_;
  toml::table* tbl_;
  std::string path_;
};

// Largest case file read (a list of 1e6 [[particles]] is about 60 MiB).
inline constexpr std::size_t kMaxCaseFileBytes = std::size_t{256} << 20;

class Config {
 public:
  Config();
  ~Config();
  Config(Config&&) noexcept;
  Config& operator=(Config&&) noexcept;

  // Parse a file / string. Throws ConfigError on syntax errors (with line and column).
  static Config load(const std::filesystem::path& file);
  static Config from_string(std::string_view text, std::string name = "<string>");

  // Apply "dotted.key=value" (value parsed as TOML; a bare word is taken as a string).
  // Array elements are addressed by index: "particles.0.radius=2e-6".
  void apply_override(std::string_view assignment);

  ConfigSection root();
  const std::string& file() const { return file_; }

  // Reject keys that no section ever asked for.
  void check_unknown_keys() const;

  // The table with every default filled in, as TOML text.
  std::string resolved_toml() const;

  // A deep copy (for runs that modify a key, e.g. sweeps and bisection).
  Config clone() const;

  // Warnings of the reads since the last call (e.g. a deprecated value), each once, in order; the run
  // pipeline (run::plan) passes them to its Reporter.
  std::vector<std::string> take_warnings() { return std::exchange(*warnings_, {}); }

 private:
  friend class ConfigSection;
  std::unique_ptr<toml::table> tbl_;
  std::string file_;
  std::unique_ptr<std::vector<std::string>> used_;  // dotted keys that were read
  std::unique_ptr<std::vector<std::string>> warnings_;
};

}  // namespace agglo
