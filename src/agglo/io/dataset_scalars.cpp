#include "agglo/io/dataset_scalars.hpp"

#include <array>
#include <cctype>
#include <limits>
#include <utility>

namespace agglo::io {

namespace {
bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}
}  // namespace

std::string units_of_key(std::string_view key) {
  // First match wins: a longer suffix before the shorter one it ends with (PM's "_ug_m3" is a mass
  // concentration, not a volume).
  static const std::array<std::pair<std::string_view, std::string_view>, 10> table{{{"_m_per_s", "m s-1"},
                                                                                    {"_m_s", "m s-1"},
                                                                                    {"_seconds", "s"},
                                                                                    {"_cm3", "cm-3"},
                                                                                    {"_ug_m3", "ug m-3"},
                                                                                    {"_m3", "m3"},
                                                                                    {"_J", "J"},
                                                                                    {"_s", "s"},
                                                                                    {"_m", "m"},
                                                                                    {"_C", "C"}}};
  for (const auto& [suffix, units] : table)
    if (ends_with(key, suffix)) return std::string(units);
  return "1";
}

std::string netcdf_name(std::string name) {
  for (char& c : name)
    if (c == '/' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '_';
  if (name.empty()) return "_";
  const auto first = static_cast<unsigned char>(name[0]);
  if (!(std::isalnum(first) || first == '_' || first >= 0x80)) name[0] = '_';
  return name;
}

void add_scalars(Dataset& d, const nlohmann::json& j, const std::string& prefix) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string name = prefix + it.key();
    const auto& v = it.value();
    if (v.is_object()) {
      add_scalars(d, v, name + "_");
      continue;
    }
    if (d.find(name) || !(v.is_number() || v.is_boolean() || v.is_null())) continue;
    std::string long_name = name;
    for (char& c : long_name)
      if (c == '_') c = ' ';
    if (v.is_boolean() || v.is_number_integer())
      d.add_ints(name, {}, v.is_boolean() ? "1" : units_of_key(name), long_name,
                 {v.is_boolean() ? std::int64_t{v.get<bool>()} : v.get<std::int64_t>()})
          .attributes = v.is_boolean() ? nlohmann::json{{"flag_values", {0, 1}}, {"flag_meanings", "false true"}}
                                       : nlohmann::json::object();
    else
      d.add(name, {}, units_of_key(name), long_name,
            {v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>()});
  }
}

Variable& add_column(Dataset& d, const std::string& name, const std::string& dim, std::string units,
                     std::string long_name, std::vector<double> values) {
  d.add_dim(dim, values.size());
  return d.add(name, {dim}, std::move(units), std::move(long_name), std::move(values));
}

Variable& add_int_column(Dataset& d, const std::string& name, const std::string& dim, std::string units,
                         std::string long_name, std::vector<std::int64_t> values) {
  d.add_dim(dim, values.size());
  return d.add_ints(name, {dim}, std::move(units), std::move(long_name), std::move(values));
}

}  // namespace agglo::io
