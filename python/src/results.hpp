#pragma once
// agglo.Result: what a command function returns — the summary (a dict), the seed, the output folder and
// the run's labelled arrays (io::Dataset) as NumPy arrays sharing the dataset's storage.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // in every file: the casters of std types must agree (ODR)

#include "agglo/io/dataset.hpp"

namespace agglo::python {

struct Result {
  std::string command;
  nlohmann::json summary;
  long long seed = 0;
  std::optional<std::string> out;     // the output folder; none when the run wrote nothing for the user
  io::DatasetPtr data;                // null when the command gives no arrays
  std::vector<std::string> messages;  // the run's result lines (the CLI prints them on stdout)
};

// A JSON value as the Python object json.loads would give.
pybind11::object to_python(const nlohmann::json& j);

}  // namespace agglo::python
