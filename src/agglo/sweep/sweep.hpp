#pragma once
// Generic parameter sweep: independent runs of one command over values of one config key.
// Each case is a Config::clone() of the base case with `key=value` applied (Config::apply_override),
// runs in its own output sub-folder, and returns a JSON summary; the cases run concurrently on
// std::threads (each with its share of the OpenMP threads), and the table is written in value order,
// so the result does not depend on scheduling. Used by `agglo sweep` (acoustic command; the DEM
// commands can register their own runner).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/core/config.hpp"
#include "agglo/core/output.hpp"

namespace agglo::sweep {

struct SweepCase {
  std::size_t index = 0;
  std::string value;        // as given on the command line
  std::string assignment;   // "key=value"
};

// Runs one case: cfg is the clone with the override applied; out its own folder.
using CaseRunner = std::function<nlohmann::json(Config& cfg, const OutputDir& out, const SweepCase& c)>;

// "v1,v2,..." -> values (whitespace trimmed; empty entries rejected with ConfigError).
std::vector<std::string> split_values(const std::string& list);

// Folder name of a case: "case_<index>_<value with unsafe characters replaced>".
std::string case_folder(std::size_t index, const std::string& value);

// Clones and overrides every case first (ConfigError before anything runs), calls `validate` on each
// clone (e.g. the full parse of the command), then runs all cases on up to `threads` threads
// (0 = all cores). Returns the summaries in value order. An exception in a case is rethrown after
// all running cases have finished (the first one in value order).
std::vector<nlohmann::json> run_sweep(const Config& base, const std::string& key, const std::vector<std::string>& values,
                                      const OutputDir& out, const CaseRunner& run,
                                      const std::function<void(Config&)>& validate, int threads, bool verbose);

// Flattens numbers/booleans of a JSON object ("a.b.c" keys for nested objects).
void flatten_scalars(const nlohmann::json& j, const std::string& prefix, std::vector<std::pair<std::string, double>>& out);

// sweep.csv: index, <key>, case folder, then the union of scalar summary fields (in first-seen order).
void write_table(const OutputDir& out, const std::string& key, const std::vector<std::string>& values,
                 const std::vector<nlohmann::json>& summaries);

}  // namespace agglo::sweep
