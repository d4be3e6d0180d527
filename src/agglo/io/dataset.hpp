#pragma once
// A run's results as named, labelled arrays — the data model of NetCDF and xarray: dimensions with
// lengths, variables over dimensions with CF-style `units` and `long_name`, and global attributes.
// Built from a command's observations (writers/<command>.hpp, its tables through io::Table); consumed
// by the NetCDF writer (results.nc) and by the Python module (NumPy arrays that share the variables'
// storage).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace agglo::io {

struct Variable {
  std::string name;                  // NetCDF variable name, e.g. "kinetic_energy"
  std::vector<std::string> dims;     // dimension names, outermost first (row-major data)
  std::string units;                 // UDUNITS string, e.g. "J", "m s-1", "m-3", "1"
  std::string long_name;             // one-line description
  bool integer = false;              // true: the values live in `ints`, else in `reals`
  std::vector<double> reals;
  std::vector<std::int64_t> ints;
  nlohmann::json attributes = nlohmann::json::object();  // further attributes (e.g. flag_meanings)
  std::size_t size() const { return integer ? ints.size() : reals.size(); }
};

struct Dataset {
  std::vector<std::pair<std::string, std::size_t>> dims;      // in order of definition
  std::vector<Variable> variables;                            // in order of definition
  nlohmann::json attributes = nlohmann::json::object();       // global attributes (strings, numbers)

  // Defines a dimension (same name and length again is a no-op; another length throws std::logic_error).
  void add_dim(const std::string& name, std::size_t length);
  // Adds a real / integer variable; throws std::logic_error when a dimension is undefined or the
  // number of values is not the product of the dimension lengths.
  Variable& add(const std::string& name, std::vector<std::string> dims, std::string units, std::string long_name,
                std::vector<double> values);
  Variable& add_ints(const std::string& name, std::vector<std::string> dims, std::string units,
                     std::string long_name, std::vector<std::int64_t> values);
  std::size_t dim_length(const std::string& name) const;  // throws std::logic_error when undefined
  const Variable* find(const std::string& name) const;    // null when absent
};

using DatasetPtr = std::shared_ptr<const Dataset>;

}  // namespace agglo::io
