#pragma once
// An io::Dataset as JSON and back, exactly: what an ensemble job returns (its journal line, and the
// message an MPI rank sends), so that ensemble statistics never read member folders back from disk.
//   {"dims": [[name, length], ...],
//    "variables": [{"name", "dims", "units", "long_name", "integer", "values", "attributes"}, ...],
//    "attributes": {...}}
// Finite doubles are JSON numbers (nlohmann writes the shortest text that parses back to the same bits,
// -0.0 included); a non-finite double is the string "inf", "-inf" or "nan:<16 hex digits of its bits>",
// so NaN payloads and signs round-trip bitwise too. Integer variables are JSON integers.
#include <nlohmann/json.hpp>

#include "agglo/io/dataset.hpp"

namespace agglo::io {

nlohmann::json dataset_to_json(const Dataset& d);

// The inverse of dataset_to_json; std::invalid_argument when `j` is not such an object (bad shape,
// unknown dimension, wrong number of values).
Dataset dataset_from_json(const nlohmann::json& j);

}  // namespace agglo::io
