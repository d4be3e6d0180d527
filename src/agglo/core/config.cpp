#include "agglo/core/config.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo {

namespace {

std::string repr(const toml::node& n) {
  std::ostringstream os;
  if (auto s = n.as_string()) {
    os << '"' << s->get() << '"';
  } else if (auto d = n.as_floating_point()) {
    os << fmt::format("{:g}", d->get());
  } else if (auto i = n.as_integer()) {
    os << i->get();
  } else if (auto b = n.as_boolean()) {
    os << (b->get() ? "true" : "false");
  } else if (n.is_table()) {
    os << "<table>";
  } else if (auto a = n.as_array()) {
    os << '[';
    for (std::size_t k = 0; k < a->size(); ++k) os << (k ? ", " : "") << repr(*a->get(k));
    os << ']';
  } else {
    os << "<date/time>";
  }
  std::string s = os.str();
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

std::string fmt_bound(double v) {
  if (v >= 1e307) return "inf";
  if (v <= -1e307) return "-inf";
  return fmt::format("{:g}", v);
}

std::optional<double> as_real(const toml::node& n) {
  if (auto d = n.as_floating_point()) return d->get();
  if (auto i = n.as_integer()) return static_cast<double>(i->get());
  return std::nullopt;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

}  // namespace

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (lo_closed ? v < lo : v <= lo) return false;
  if (hi_closed ? v > hi : v >= hi) return false;
  return true;
}

std::string Range::describe() const {
  std::string s = fmt::format("{}{}, {}{}", lo_closed && lo > -1e307 ? '[' : '(', fmt_bound(lo),
                              fmt_bound(hi), hi_closed && hi < 1e307 ? ']' : ')');
  if (!unit.empty()) s += " " + unit;
  return s;
}

// ---------------------------------------------------------------------------------------------
Config::Config()
    : tbl_(std::make_unique<toml::table>()),
      used_(std::make_unique<std::vector<std::string>>()),
      warnings_(std::make_unique<std::vector<std::string>>()) {}
Config::~Config() = default;
Config::Config(Config&&) noexcept = default;
Config& Config::operator=(Config&&) noexcept = default;

Config Config::from_string(std::string_view text, std::string name) {
  Config c;
  c.file_ = std::move(name);
  try {
    *c.tbl_ = toml::parse(text, c.file_);
  } catch (const toml::parse_error& e) {
    throw ConfigError(fmt::format("{}:{}:{}: TOML syntax error: {}", c.file_, e.source().begin.line,
                                  e.source().begin.column, e.description()));
  }
  return c;
}

Config Config::load(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ConfigError(fmt::format("{}: cannot open case file", file.string()));
  // Read at most kMaxCaseFileBytes + 1 bytes, so that /dev/zero or a huge file cannot exhaust memory.
  std::string text;
  char chunk[65536];
  while (text.size() <= kMaxCaseFileBytes && in.read(chunk, sizeof chunk).gcount() > 0)
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxCaseFileBytes)
    throw ConfigError(fmt::format("{}: case file larger than {} MiB (is it a case file?)", file.string(),
                                  kMaxCaseFileBytes >> 20));
  if (text.empty())  // a 0-byte file is a mistake, not "all defaults" (a comment or newline is enough)
    throw ConfigError(fmt::format("{}: empty case file", file.string()));
  return from_string(text, file.string());
}

Config Config::clone() const {
  Config c;
  *c.tbl_ = *tbl_;
  c.file_ = file_;
  return c;
}

namespace {
// The dotted key of a --set assignment, whitespace removed, split at '.'; every segment non-empty.
std::vector<std::string> override_key(std::string_view assignment, std::string key) {
  key.erase(std::remove_if(key.begin(), key.end(), [](unsigned char c) { return std::isspace(c) != 0; }), key.end());
  if (key.empty())
    throw ConfigError(fmt::format("--set '{}': expected KEY=VALUE, e.g. --set section.key=value", assignment));
  std::vector<std::string> parts;
  for (std::size_t b = 0;;) {
    const auto dot = key.find('.', b);
    parts.push_back(key.substr(b, dot == std::string::npos ? std::string::npos : dot - b));
    if (parts.back().empty()) throw ConfigError(fmt::format("--set '{}': empty key segment", assignment));
    if (dot == std::string::npos) return parts;
    b = dot + 1;
  }
}

// The TOML value of a --set assignment; a bare word that is not TOML is taken as a string.
std::unique_ptr<toml::node> override_value(std::string_view assignment, const std::string& value) {
  toml::table t;
  try {
    t = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    if (std::any_of(value.begin(), value.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; }))
      throw ConfigError(fmt::format("--set '{}': the value contains a control character", assignment));
    return std::make_unique<toml::value<std::string>>(value);
  }
  if (t.size() != 1 || !t.contains("v"))
    throw ConfigError(fmt::format("--set '{}': one KEY=VALUE assignment per --set", assignment));
  return std::unique_ptr<toml::node>(
      t.get("v")->visit([](auto& n) -> toml::node* { return new std::remove_cvref_t<decltype(n)>(n); }));
}
// Refuses an index into an array the case does not have ("particles.99.radius" in a case without
// [[particles]]), before anything is changed; indices into existing arrays are checked by apply_override.
void check_indices(const toml::table& root, std::string_view assignment, const std::vector<std::string>& parts) {
  const toml::node* cur = &root;
  for (std::size_t k = 1; k < parts.size() && cur; ++k) {
    const toml::table* t = cur->as_table();
    const toml::node* next = t ? t->get(parts[k - 1]) : nullptr;
    if (!next && t && parts[k].find_first_not_of("0123456789") == std::string::npos)
      throw ConfigError(fmt::format("--set '{}': '{}' is not a valid index (the case has no array '{}': 0 elements)",
                                    assignment, parts[k], parts[k - 1]));
    cur = next;
  }
}
}  // namespace

void Config::apply_override(std::string_view assignment) {
  auto eq = assignment.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw ConfigError(fmt::format("--set '{}': expected KEY=VALUE, e.g. --set section.key=value", assignment));
  const std::vector<std::string> parts = override_key(assignment, std::string(assignment.substr(0, eq)));
  const std::unique_ptr<toml::node> parsed = override_value(assignment, std::string(assignment.substr(eq + 1)));
  check_indices(*tbl_, assignment, parts);
  toml::node* cur = tbl_.get();
  for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
    const auto& p = parts[k];
    if (auto t = cur->as_table()) {
      if (!t->contains(p)) t->insert(p, toml::table{});
      cur = t->get(p);
    } else if (auto a = cur->as_array()) {
      char* end = nullptr;
      long idx = std::strtol(p.c_str(), &end, 10);
      if (*end != '\0' || idx < 0 || static_cast<std::size_t>(idx) >= a->size())
        throw ConfigError(fmt::format("--set '{}': '{}' is not a valid index (array has {} elements)",
                                      assignment, p, a->size()));
      cur = a->get(static_cast<std::size_t>(idx));
    } else {
      throw ConfigError(fmt::format("--set '{}': '{}' is not a table", assignment, p));
    }
  }
  const auto& last = parts.back();
  if (auto t = cur->as_table()) {
    parsed->visit([&](auto& n) { t->insert_or_assign(last, n); });
  } else if (auto a = cur->as_array()) {
    char* end = nullptr;
    long idx = std::strtol(last.c_str(), &end, 10);
    if (*end != '\0' || idx < 0 || static_cast<std::size_t>(idx) >= a->size())
      throw ConfigError(fmt::format("--set '{}': '{}' is not a valid index", assignment, last));
    parsed->visit([&](auto& n) { a->replace(a->begin() + idx, n); });
  } else {
    throw ConfigError(fmt::format("--set '{}': parent of '{}' is not a table", assignment, last));
  }
}

ConfigSection Config::root() { return ConfigSection(this, tbl_.get(), ""); }

std::string Config::resolved_toml() const {
  std::ostringstream os;
  os << *tbl_ << '\n';
  return os.str();
}

void Config::check_unknown_keys() const {
  std::set<std::string> used(used_->begin(), used_->end());
  auto known_in = [&](const std::string& prefix) {
    std::vector<std::string> out;
    for (const auto& u : used) {
      if (prefix.empty() ? u.find('.') == std::string::npos
                         : (u.rfind(prefix + ".", 0) == 0 && u.find('.', prefix.size() + 1) == std::string::npos)) {
        std::string leaf = prefix.empty() ? u : u.substr(prefix.size() + 1);
        if (!std::all_of(leaf.begin(), leaf.end(), ::isdigit)) out.push_back(leaf);
      }
    }
    return out;
  };
  // Generic path of an array element "particles.3.x" -> known keys registered under "particles.0".
  std::function<void(const toml::table&, const std::string&)> walk = [&](const toml::table& t, const std::string& p) {
    for (const auto& [k, node] : t) {
      std::string full = p.empty() ? std::string(k.str()) : p + "." + std::string(k.str());
      if (!used.count(full)) {
        auto known = known_in(p);
        throw ConfigError(fmt::format("{}: unknown key '{}'{}", file_, cut_for_message(full),  // a 1 MB key: cut
                                      known.empty() ? std::string(" (this section takes no keys)")
                                                    : fmt::format(" (allowed{}: {})",
                                                                  p.empty() ? "" : " in [" + cut_for_message(p) + "]",
                                                                  join(known))));
      }
      if (auto sub = node.as_table()) walk(*sub, full);
      if (auto arr = node.as_array()) {
        for (std::size_t i = 0; i < arr->size(); ++i)
          if (auto st = arr->get(i)->as_table()) walk(*st, full + "." + std::to_string(i));
      }
    }
  };
  walk(*tbl_, "");
}

// ---------------------------------------------------------------------------------------------
std::string ConfigSection::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

toml::node* ConfigSection::lookup(std::string_view key) const { return tbl_->get(key); }

void ConfigSection::mark(std::string_view key) const { cfg_->used_->push_back(key_path(key)); }

bool ConfigSection::has(std::string_view key) const { return tbl_->contains(key); }

void ConfigSection::fail(std::string_view key, std::string_view what) const {
  throw ConfigError(fmt::format("{}: key '{}': {}", cfg_->file_, key_path(key), what));
}

void ConfigSection::fail_value(std::string_view key, std::string_view what) const {
  auto* n = lookup(key);
  throw ConfigError(fmt::format("{}: key '{}' = {}: {}", cfg_->file_, key_path(key), n ? repr(*n) : "<missing>", what));
}

void ConfigSection::warn(std::string_view key, std::string_view what) const {
  auto* n = lookup(key);
  std::string w = fmt::format("{}: key '{}' = {}: {}", cfg_->file_, key_path(key), n ? repr(*n) : "<missing>", what);
  auto& all = *cfg_->warnings_;
  if (std::find(all.begin(), all.end(), w) == all.end()) all.push_back(std::move(w));
}

std::optional<bool> ConfigSection::boolean_if_set(std::string_view key) const {
  mark(key);
  auto* n = lookup(key);
  if (auto b = n ? n->as_boolean() : nullptr) return b->get();
  return std::nullopt;
}

std::optional<std::string> ConfigSection::string_if_set(std::string_view key) const {
  mark(key);
  auto* n = lookup(key);
  if (auto s = n ? n->as_string() : nullptr) return s->get();
  return std::nullopt;
}

double ConfigSection::number(std::string_view key, std::optional<double> def, const Range& range) const {
  mark(key);
  auto* n = lookup(key);
  if (!n) {
    if (!def) fail(key, fmt::format("required key is missing (a number in {})", range.describe()));
    tbl_->insert(key, *def);
    return *def;
  }
  auto v = as_real(*n);
  if (!v) fail_value(key, fmt::format("expected a number in {}", range.describe()));
  if (!std::isfinite(*v)) fail_value(key, fmt::format("must be finite, in {}", range.describe()));
  if (!range.contains(*v)) fail_value(key, fmt::format("out of range, allowed {}", range.describe()));
  return *v;
}

std::int64_t ConfigSection::integer(std::string_view key, std::optional<std::int64_t> def, std::int64_t lo,
                                    std::int64_t hi) const {
  mark(key);
  auto* n = lookup(key);
  std::string rng = fmt::format("[{}, {}]", lo, hi);
  if (!n) {
    if (!def) fail(key, fmt::format("required key is missing (an integer in {})", rng));
    tbl_->insert(key, *def);
    return *def;
  }
  std::int64_t v;
  if (auto i = n->as_integer()) {
    v = i->get();
  } else if (auto d = n->as_floating_point(); d && std::isfinite(d->get()) && d->get() == std::floor(d->get()) &&
                                               std::abs(d->get()) < 9e15) {
    v = static_cast<std::int64_t>(d->get());
  } else {
    fail_value(key, fmt::format("expected an integer in {}", rng));
  }
  if (v < lo || v > hi) fail_value(key, fmt::format("out of range, allowed {}", rng));
  return v;
}

bool ConfigSection::boolean(std::string_view key, std::optional<bool> def) const {
  mark(key);
  auto* n = lookup(key);
  if (!n) {
    if (!def) fail(key, "required key is missing (true or false)");
    tbl_->insert(key, *def);
    return *def;
  }
  if (auto b = n->as_boolean()) return b->get();
  fail_value(key, "expected true or false");
}

std::string ConfigSection::string(std::string_view key, std::optional<std::string> def) const {
  mark(key);
  auto* n = lookup(key);
  if (!n) {
    if (!def) fail(key, "required key is missing (a string)");
    tbl_->insert(key, *def);
    return *def;
  }
  if (auto s = n->as_string()) return s->get();
  fail_value(key, "expected a string");
}

std::string ConfigSection::choice(std::string_view key, std::optional<std::string> def,
                                  const std::vector<std::string_view>& allowed) const {
  std::string opts;
  for (auto a : allowed) opts += (opts.empty() ? "\"" : ", \"") + std::string(a) + "\"";
  mark(key);
  auto* n = lookup(key);
  if (!n) {
    if (!def) fail(key, fmt::format("required key is missing (one of {})", opts));
    tbl_->insert(key, *def);
    return *def;
  }
  auto s = n->as_string();
  if (!s) fail_value(key, fmt::format("expected one of {}", opts));
  for (auto a : allowed)
    if (s->get() == a) return s->get();
  fail_value(key, fmt::format("unknown choice, allowed {}", opts));
}

std::vector<double> ConfigSection::numbers(std::string_view key, std::optional<std::vector<double>> def,
                                           const Range& range) const {
  mark(key);
  auto* n = lookup(key);
  if (!n) {
    if (!def) fail(key, fmt::format("required key is missing (an array of numbers in {})", range.describe()));
    toml::array a;
    for (double d : *def) a.push_back(d);
    tbl_->insert(key, std::move(a));
    return *def;
  }
  auto a = n->as_array();
  if (!a) fail_value(key, fmt::format("expected an array of numbers in {}", range.describe()));
  std::vector<double> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    auto v = as_real(*a->get(i));
    if (!v || !range.contains(*v))
      fail_value(key, fmt::format("element {} must be a number in {}", i, range.describe()));
    out.push_back(*v);
  }
  return out;
}

Vec3 ConfigSection::vec3(std::string_view key, std::optional<Vec3> def, const Range& range) const {
  std::optional<std::vector<double>> d;
  if (def) d = std::vector<double>{def->x, def->y, def->z};
  auto v = numbers(key, d, range);
  if (v.size() != 3) fail_value(key, "expected an array of 3 numbers [x, y, z]");
  return {v[0], v[1], v[2]};
}

ConfigSection ConfigSection::section(std::string_view key) const {
  mark(key);
  auto* n = lookup(key);
  if (!n) {
    tbl_->insert(key, toml::table{});
    n = lookup(key);
  }
  auto t = n->as_table();
  if (!t) fail_value(key, "expected a table [section]");
  return ConfigSection(cfg_, t, key_path(key));
}

std::vector<ConfigSection> ConfigSection::tables(std::string_view key) const {
  mark(key);
  std::vector<ConfigSection> out;
  auto* n = lookup(key);
  if (!n) return out;
  auto a = n->as_array();
  if (!a) fail_value(key, fmt::format("expected an array of tables ([[{}]])", key));
  for (std::size_t i = 0; i < a->size(); ++i) {
    auto t = a->get(i)->as_table();
    if (!t) fail_value(key, fmt::format("element {} is not a table", i));
    cfg_->used_->push_back(key_path(key) + "." + std::to_string(i));
    out.push_back(ConfigSection(cfg_, t, key_path(key) + "." + std::to_string(i)));
  }
  return out;
}

}  // namespace agglo
