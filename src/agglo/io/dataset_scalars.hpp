#pragma once
// Scalars of a JSON summary (result.json, summary.json, ...) as 0-d variables of a Dataset, named like
// their JSON keys (nested objects: "<parent>_<key>"); units read from the key's suffix.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/io/dataset.hpp"

namespace agglo::io {

// UDUNITS string of a value named by its key's suffix: "_J" J, "_s" / "_seconds" s, "_m" m,
// "_m_s" / "_m_per_s" m s-1, "_cm3" cm-3, "_m3" m3; "1" otherwise (counts, ratios, flags).
std::string units_of_key(std::string_view key);

// Adds every number and boolean of `j` (an object) as a 0-d variable "<prefix><key>": integers and
// booleans (0/1) as integer variables, other numbers as reals, null as NaN; recurses into objects
// with "<prefix><key>_"; skips strings, arrays and keys already defined.
void add_scalars(Dataset& d, const nlohmann::json& j, const std::string& prefix = "");

// `name` as a valid netCDF name: '/' and control characters become '_', and so does a first character
// that is not a letter, digit or '_'.
std::string netcdf_name(std::string name);

// Adds a real table column over `dim`; the dimension is defined from the column's length.
Variable& add_column(Dataset& d, const std::string& name, const std::string& dim, std::string units,
                     std::string long_name, std::vector<double> values);
Variable& add_int_column(Dataset& d, const std::string& name, const std::string& dim, std::string units,
                         std::string long_name, std::vector<std::int64_t> values);

// One field of every row as a column: reals_of(rows, [](const Row& r) { return r.t; }).
template <class Rows, class F>
std::vector<double> reals_of(const Rows& rows, F field) {
  std::vector<double> out;
  for (const auto& r : rows) out.push_back(static_cast<double>(field(r)));
  return out;
}
template <class Rows, class F>
std::vector<std::int64_t> ints_of(const Rows& rows, F field) {
  std::vector<std::int64_t> out;
  for (const auto& r : rows) out.push_back(static_cast<std::int64_t>(field(r)));
  return out;
}

}  // namespace agglo::io
