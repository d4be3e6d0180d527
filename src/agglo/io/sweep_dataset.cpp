#include "agglo/io/sweep_dataset.hpp"

#include <algorithm>
#include <charconv>
#include <limits>

#include "agglo/io/config_units.hpp"
#include "agglo/io/dataset_scalars.hpp"

namespace agglo::io {

namespace {

bool as_number(const std::string& s, double& x) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
  return ec == std::errc() && end == s.data() + s.size();
}

// The values of column k of `rows` as numbers, or false when one is not a number.
bool numeric_column(const std::vector<std::vector<std::string>>& rows, std::size_t k, std::vector<double>& out) {
  for (const auto& r : rows) {
    double x = 0;
    if (k >= r.size() || !as_number(r[k], x)) return false;
    out.push_back(x);
  }
  return true;
}

void add_summaries(Dataset& d, const std::vector<SweepRow>& rows) {
  std::vector<std::vector<std::pair<std::string, double>>> flat;
  const auto cols = summary_columns(rows, flat);
  for (const auto& c : cols) {
    if (d.find(netcdf_name(c))) continue;
    std::vector<double> v(rows.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (const auto& [k, x] : flat[i])
        if (k == c) v[i] = x;
    d.add(netcdf_name(c), {"case"}, units_of_key(c), "case summary " + c, v);
  }
}

}  // namespace

void add_key_columns(Dataset& d, const std::string& dim, const std::vector<std::string>& keys,
                     const std::vector<std::vector<std::string>>& rows) {
  for (std::size_t k = 0; k < keys.size(); ++k) {
    std::vector<double> x;
    if (numeric_column(rows, k, x)) {
      d.add(netcdf_name(keys[k]), {dim}, udunits_of_config_key(keys[k]), "swept value of " + keys[k], x)
          .attributes["config_key"] = keys[k];
      continue;
    }
    nlohmann::json values = nlohmann::json::array();
    for (const auto& r : rows) values.push_back(k < r.size() ? r[k] : "");
    d.attributes[netcdf_name(keys[k])] = values.dump();
  }
}

Dataset sweep_dataset(const std::vector<std::string>& keys, const std::vector<SweepRow>& rows) {
  Dataset d;
  std::vector<std::int64_t> index;
  nlohmann::json folders = nlohmann::json::array();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    index.push_back(static_cast<std::int64_t>(i));
    folders.push_back(rows[i].folder);
  }
  add_int_column(d, "case", "case", "1", "case index (sweep.csv index)", index);
  std::vector<std::vector<std::string>> values;
  for (const auto& r : rows) values.push_back(r.values);
  add_key_columns(d, "case", keys, values);
  d.attributes["case_folders"] = folders.dump();
  add_summaries(d, rows);
  return d;
}

}  // namespace agglo::io
