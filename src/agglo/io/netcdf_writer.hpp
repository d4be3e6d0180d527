#pragma once
// results.nc: a Dataset (io/dataset.hpp) as one NetCDF-4 file (Unidata netCDF-C library). Dimensions as
// defined, every variable with its `units` and `long_name` attributes plus its further attributes,
// integer variables as NC_INT64 and reals as NC_DOUBLE, global attributes from the dataset's JSON
// object (strings as text, integers as NC_INT64, other numbers as NC_DOUBLE, booleans as 0/1, arrays of
// numbers as numeric arrays, anything else as its JSON text). The file is written under
// "<name>.tmp-<pid>" and renamed when complete, so a failed or killed write never leaves a partial
// results.nc (OutputDir removes a killed run's temporary file).
#include <mutex>
#include <string>

#include "agglo/io/dataset.hpp"
#include "agglo/io/output_dir.hpp"

namespace agglo::io {

inline constexpr const char* kResultsFile = "results.nc";

// Writes `d` to out/name, with `extra_attributes` (an object) as further global attributes that replace
// the dataset's own of the same name; std::runtime_error naming the file and netCDF's message on any
// failure (the temporary file is removed and an earlier file of that name is left as it was).
// The NetCDF-C library is not thread-safe (sweep cases and Python threads write concurrently): every call
// into it, writer and reader (netcdf_reader.hpp), holds this mutex.
std::mutex& netcdf_library_mutex();

void write_netcdf(const OutputDir& out, const Dataset& d, const std::string& name = kResultsFile,
                  const nlohmann::json& extra_attributes = nlohmann::json::object());

}  // namespace agglo::io
