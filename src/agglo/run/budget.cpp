#include "agglo/run/budget.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::run {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A finite decimal number (digits, optional fraction and exponent) filling `text`; nullopt otherwise.
std::optional<double> plain_number(std::string_view text) {
  if (text.empty() || !(std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '.')) return std::nullopt;
  const std::string s(text);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string trimmed(std::string_view v) {
  const auto b = v.find_first_not_of(" \t"), e = v.find_last_not_of(" \t");
  return b == std::string_view::npos ? std::string() : std::string(v.substr(b, e - b + 1));
}

}  // namespace

double parse_size(std::string_view value, std::string_view source) {
  std::string s = trimmed(value);
  double scale = 1.0;
  if (!s.empty()) {
    const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(s.back())));
    const std::string_view units = "KMGT";
    if (const auto k = units.find(u); k != std::string_view::npos) {
      scale = std::pow(1024.0, static_cast<double>(k + 1));
      s.pop_back();
    }
  }
  const auto v = plain_number(s);
  if (!v || *v * scale < 1.0 || !std::isfinite(*v * scale))
    throw ConfigError(fmt::format("{} = '{}': not a size; give a number of bytes >= 1, optionally with a suffix K, "
                                  "M, G or T (powers of 1024), e.g. 8G",
                                  source, one_line(value)));
  return std::floor(*v * scale);
}

double parse_steps(std::string_view value, std::string_view source) {
  const auto v = plain_number(trimmed(value));
  if (!v || *v < 1.0)
    throw ConfigError(fmt::format("{} = '{}': not a step count; give a number >= 1 of particle-steps, e.g. 1e12",
                                  source, one_line(value)));
  return std::floor(*v);
}

std::optional<double> read_memory_limit(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string word;
  if (!(in >> word) || word == "max") return std::nullopt;
  const auto v = plain_number(word);
  if (!v || *v <= 0.0) return std::nullopt;
  return *v;
}

double cgroup_memory_limit(const std::filesystem::path& root, const std::filesystem::path& self) {
  double limit = kInf;
  auto take = [&](const std::filesystem::path& dir, const char* file) {
    // The cgroup and each of its parents up to `dir`'s hierarchy root may set a limit.
    for (std::filesystem::path p = dir;; p = p.parent_path()) {
      if (const auto v = read_memory_limit(p / file)) limit = std::min(limit, *v);
      if (!p.has_relative_path() || p == p.parent_path() || p.filename().empty()) break;
    }
  };
  std::ifstream in(self);
  std::string line;
  while (std::getline(in, line)) {  // "0::/path" (v2) or "4:memory:/path" (v1)
    const auto a = line.find(':'), b = line.find(':', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    const std::string controllers = line.substr(a + 1, b - a - 1), path = line.substr(b + 1);
    const std::filesystem::path rel = std::filesystem::path(path).relative_path();
    if (controllers.empty()) take(root / rel, "memory.max");
    std::stringstream list(controllers);
    for (std::string c; std::getline(list, c, ',');)
      if (c == "memory") take(root / "memory" / rel, "memory.limit_in_bytes");
  }
  if (const auto v = read_memory_limit(root / "memory.max")) limit = std::min(limit, *v);
  if (const auto v = read_memory_limit(root / "memory" / "memory.limit_in_bytes")) limit = std::min(limit, *v);
  return limit;
}

double physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? static_cast<double>(pages) * static_cast<double>(size) : kInf;
}

double default_memory_budget() {
  const double usable = std::min(cgroup_memory_limit(), physical_memory());
  return std::isfinite(usable) ? std::floor(kMemoryFraction * usable) : 64.0 * 1024.0 * 1024.0 * 1024.0;
}

Budgets resolve_budgets(const BudgetArgs& cli) {
  Budgets b;
  auto pick = [](const std::string& given, const char* option, const char* env, auto parse, double def) {
    if (!given.empty()) return parse(given, option);
    if (const char* e = std::getenv(env)) return parse(e, env);
    return def;
  };
  b.max_steps = pick(cli.max_steps, "--max-steps", "AGGLO_MAX_STEPS", parse_steps, kDefaultMaxSteps);
  b.max_memory_bytes = pick(cli.max_memory, "--max-memory", "AGGLO_MAX_MEMORY", parse_size, default_memory_budget());
  b.max_output_bytes = pick(cli.max_output, "--max-output", "AGGLO_MAX_OUTPUT", parse_size, kDefaultMaxOutputBytes);
  return b;
}

std::string format_bytes(double bytes) {
  if (!std::isfinite(bytes)) return "more than 1e308 B";
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
  int k = 0;
  while (k < 5 && bytes >= 1024.0) {
    bytes /= 1024.0;
    ++k;
  }
  return fmt::format("{:.3g} {}", bytes, units[k]);
}

std::string format_steps(double steps) {
  return std::isfinite(steps) ? fmt::format("{:.3g} steps", steps) : std::string("more than 1e308 steps");
}

namespace {
std::string key_list(const EstimateItem& item) {
  std::string s;
  for (const auto& k : item.keys) s += (s.empty() ? "" : ", ") + k;
  return s.empty() ? std::string("the case") : s;
}

void check_one(const EstimateItem& item, double budget, std::string_view what, std::string_view quantity,
               std::string_view option, std::string_view env, const std::string& est, const std::string& bud) {
  if (item.value <= budget) return;
  throw LimitError(fmt::format("{}: the estimated {} {} (driven by {}) exceeds the {} budget {}; check those keys, "
                                "or raise the budget with {} or {}",
                                what, quantity, est, key_list(item), quantity == "steps" ? "step" : quantity, bud,
                                option, env));
}
}  // namespace

std::string describe(const Estimate& e, const Budgets& b) {
  auto line = [](const char* what, const EstimateItem& item, const std::string& est, const std::string& bud,
                 double budget) {
    return fmt::format("  {:<7} {:<26} budget {:<26} {}  driven by {}\n", what, est, bud,
                       item.value <= budget ? "ok     " : "EXCEEDS", key_list(item));
  };
  return line("steps", e.steps, format_steps(e.steps.value), format_steps(b.max_steps), b.max_steps) +
         line("memory", e.memory, format_bytes(e.memory.value), format_bytes(b.max_memory_bytes), b.max_memory_bytes) +
         line("output", e.output, format_bytes(e.output.value), format_bytes(b.max_output_bytes), b.max_output_bytes);
}

std::string format_duration(double seconds) {
  if (seconds < 60.0) return fmt::format("{:.3g} s", seconds);
  if (seconds < 3600.0) return fmt::format("{:.3g} min", seconds / 60.0);
  if (seconds < 86400.0) return fmt::format("{:.3g} h", seconds / 3600.0);
  return fmt::format("{:.3g} d", seconds / 86400.0);
}

std::string describe_time(double steps, double seconds_per_step) {
  if (!(seconds_per_step > 0.0)) return "  time    not estimated for this command\n";
  const double t = steps * seconds_per_step;
  const char* cost_class = t < 60.0 ? "seconds" : t < 3600.0 ? "minutes" : t < 86400.0 ? "hours"
                         : t < 30 * 86400.0 ? "days" : "months or more";
  return fmt::format("  time    at most {:<18} cost class {:<15} ({:.3g} s of one thread: {:.2g} s per step, "
                     "measured; n threads at best 1/n)\n", format_duration(t), cost_class, t, seconds_per_step);
}

void check_budgets(const Estimate& e, const Budgets& b, std::string_view what) {
  check_one(e.steps, b.max_steps, what, "steps", "--max-steps", "AGGLO_MAX_STEPS", format_steps(e.steps.value),
            format_steps(b.max_steps));
  check_one(e.memory, b.max_memory_bytes, what, "memory", "--max-memory", "AGGLO_MAX_MEMORY",
            format_bytes(e.memory.value), format_bytes(b.max_memory_bytes));
  check_one(e.output, b.max_output_bytes, what, "output", "--max-output", "AGGLO_MAX_OUTPUT",
            format_bytes(e.output.value), format_bytes(b.max_output_bytes));
}

}  // namespace agglo::run
