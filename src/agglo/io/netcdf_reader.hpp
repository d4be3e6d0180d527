#pragma once
// Reads a NetCDF file (classic or NetCDF-4, Unidata netCDF-C library) back into a Dataset
// (io/dataset.hpp): its dimensions, every variable of a numeric type (integer types into `ints`,
// floating types into `reals`, row-major), each variable's `units` and `long_name` and its other text or
// numeric attributes, and the global attributes (text as strings, one number as a number, several as an
// array). The inverse of write_netcdf for the files agglo writes; used to read input tables (the
// DSMC's outcome tables, docs/acoustics.md).
#include <filesystem>
#include <stdexcept>

#include "agglo/io/dataset.hpp"

namespace agglo::io {

// Thrown when the file cannot be opened or read: the message names the file and netCDF's reason.
struct NetcdfReadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

Dataset read_netcdf(const std::filesystem::path& file);

}  // namespace agglo::io
