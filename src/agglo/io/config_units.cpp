#include "agglo/io/config_units.hpp"

#include <array>
#include <cctype>
#include <sstream>

#include "agglo/core/settings_catalogue.hpp"

namespace agglo::io {

namespace {

// "m^3" -> ("m", 3); "kg" -> ("kg", 1).
std::pair<std::string, int> factor(const std::string& f) {
  const auto hat = f.find('^');
  if (hat == std::string::npos) return {f, 1};
  return {f.substr(0, hat), std::stoi(f.substr(hat + 1))};
}

// Appends base^p to a UDUNITS product ("kg" + ("m", -3) -> "kg m-3").
void append(std::string& out, const std::pair<std::string, int>& f, int sign) {
  if (!out.empty()) out += ' ';
  out += f.first;
  if (f.second * sign != 1) out += std::to_string(f.second * sign);
}

}  // namespace

std::string udunits(std::string_view unit) {
  static const std::array<std::string_view, 5> unitless{"", "-", "r_p", "F_C", "steps"};
  for (auto u : unitless)
    if (unit == u) return "1";
  const std::string text(unit);
  const auto slash = text.find('/');
  std::string out;
  std::istringstream num(text.substr(0, slash));
  for (std::string f; num >> f;)
    if (f != "1") append(out, factor(f), 1);
  if (slash != std::string::npos) {
    std::istringstream den(text.substr(slash + 1));
    for (std::string f; den >> f;) append(out, factor(f), -1);
  }
  return out.empty() ? "1" : out;
}

std::string udunits_of_config_key(std::string_view key) {
  std::string dotted;
  std::istringstream parts{std::string(key)};
  for (std::string p; std::getline(parts, p, '.');)
    if (!p.empty() && !std::isdigit(static_cast<unsigned char>(p[0]))) {
      if (!dotted.empty()) dotted += '.';
      dotted += p;
    }
  for (const auto* table : settings::all_tables())
    for (const auto* s : table->settings())
      if (s->dotted() == dotted) return udunits(s->info().unit);
  return "1";
}

}  // namespace agglo::io
