#include "agglo/io/sweep_table.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace agglo::io {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + '"';
}

void flatten_scalars(const nlohmann::json& j, const std::string& prefix,
                     std::vector<std::pair<std::string, double>>& out) {
  if (!j.is_object()) return;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string k = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_number()) out.emplace_back(k, it->get<double>());
    else if (it->is_boolean()) out.emplace_back(k, it->get<bool>() ? 1.0 : 0.0);
    else if (it->is_object()) flatten_scalars(*it, k, out);
  }
}

std::vector<std::string> summary_columns(const std::vector<SweepRow>& rows,
                                         std::vector<std::vector<std::pair<std::string, double>>>& flat) {
  std::vector<std::string> cols;
  flat.assign(rows.size(), {});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    flatten_scalars(rows[i].summary, "", flat[i]);
    for (const auto& [k, v] : flat[i])
      if (std::find(cols.begin(), cols.end(), k) == cols.end()) cols.push_back(k);
  }
  return cols;
}

void write_sweep_table(const OutputDir& out, const std::vector<std::string>& keys, const std::vector<SweepRow>& rows) {
  std::vector<std::vector<std::pair<std::string, double>>> flat;
  const auto cols = summary_columns(rows, flat);
  out.write("sweep.csv", [&](std::ostream& os) {
    os << "index";
    for (const auto& k : keys) os << ',' << csv_field(k);
    os << ",case";
    for (const auto& c : cols) os << ',' << csv_field(c);
    os << '\n';
    for (std::size_t i = 0; i < rows.size(); ++i) {
      os << i;
      for (const auto& v : rows[i].values) os << ',' << csv_field(v);
      os << ',' << csv_field(rows[i].folder);
      for (const auto& c : cols) {
        os << ',';
        auto it = std::find_if(flat[i].begin(), flat[i].end(), [&](const auto& kv) { return kv.first == c; });
        if (it != flat[i].end()) os << fmt::format("{:.10g}", it->second);
      }
      os << '\n';
    }
  });
}

}  // namespace agglo::io
