#pragma once
// sweep.csv: index, one column per swept key, case folder, then the union of the numeric and boolean
// scalars of the case summaries (nested objects flattened to "a.b.c"), in first-seen order;
// fields quoted as RFC 4180 asks.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/io/output_dir.hpp"

namespace agglo::io {

// One CSV field (RFC 4180): quoted, with '"' doubled, only when it holds a comma, quote or line break.
std::string csv_field(const std::string& text);

// Flattens numbers/booleans of a JSON object ("a.b.c" keys for nested objects).
void flatten_scalars(const nlohmann::json& j, const std::string& prefix,
                     std::vector<std::pair<std::string, double>>& out);

struct SweepRow {
  std::vector<std::string> values;  // one per key
  std::string folder;
  nlohmann::json summary;
};

// The flattened scalars of every row's summary (flat[i]) and the union of their names in first-seen
// order (the summary columns of sweep.csv and results.nc).
std::vector<std::string> summary_columns(const std::vector<SweepRow>& rows,
                                         std::vector<std::vector<std::pair<std::string, double>>>& flat);

void write_sweep_table(const OutputDir& out, const std::vector<std::string>& keys, const std::vector<SweepRow>& rows);

}  // namespace agglo::io
