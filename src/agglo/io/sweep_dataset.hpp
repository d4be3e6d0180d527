#pragma once
// results.nc of `agglo sweep` (io/dataset.hpp), the content of sweep.csv: dim case (coordinate `case`,
// sweep.csv's index); each swept key whose values are all numbers as a variable named like the key
// (other keys and the case folders as global attributes "<key>" / "case_folders", JSON arrays as text);
// the summaries' numeric and boolean scalars under their sweep.csv column names ("a.b.c"; NaN where a
// case lacks one).
#include <string>
#include <vector>

#include "agglo/io/dataset.hpp"
#include "agglo/io/sweep_table.hpp"

namespace agglo::io {

Dataset sweep_dataset(const std::vector<std::string>& keys, const std::vector<SweepRow>& rows);

// The swept keys' columns on dimension `dim` (rows[i][k]: key k's value in row i): a key whose values are
// all numbers as a variable named like the key, any other as a global attribute (JSON array as text).
void add_key_columns(Dataset& d, const std::string& dim, const std::vector<std::string>& keys,
                     const std::vector<std::vector<std::string>>& rows);

}  // namespace agglo::io
