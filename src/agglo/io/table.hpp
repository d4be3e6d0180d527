#pragma once
// An output table declared once (docs/contributing.md, "Adding an output column"): every column names
// its results.nc variable, dimensions, UDUNITS unit, long name, CSV header and CSV number format, and
// holds its values already converted for display (e.g. concentrations in cm-3). One Table renders both
// the CSV file (write_csv) and the table's variables in results.nc (add_to), so the two cannot differ.
//
// CSV: a header line, then one line per combination of the row dimensions (outermost first); a column
// over some of the row dimensions repeats its value along the others, a column whose last dimension is
// not a row dimension spreads over one CSV column per component (force: fx, fy, fz), a flag column
// writes the word of its code. results.nc: the row dimensions, then the other dimensions, in order of
// declaration; the coordinate variables (a column over the one dimension of its own name) first, then
// the other columns, each in order of declaration.
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "agglo/io/dataset.hpp"
#include "agglo/io/output_dir.hpp"

namespace agglo::io {

struct Column {
  std::string name;                // results.nc variable (and CSV header unless `csv` is set)
  std::vector<std::string> dims;   // results.nc dimensions, outermost first (default: the row dimensions)
  std::string units;               // UDUNITS string: "m", "m s-1", "cm-3", "1"
  std::string long_name;           // one line
  std::vector<std::string> csv;    // CSV header(s): one, or one per component; none: results.nc only
  std::string format;              // fmt format of one CSV value, e.g. "{:.8g}" (integers: "{}")
  std::vector<std::string> labels; // flag column: the word of each code 0, 1, ... (CSV text, flag_meanings)
  bool integer = false;            // values in `ints`, else in `reals`
  std::vector<double> reals;       // row-major over `dims`
  std::vector<std::int64_t> ints;
  nlohmann::json attributes = nlohmann::json::object();  // further results.nc attributes

  // Chained setters: t.real(...).header({"t_s"}).format("{:.8g}").
  Column& header(std::vector<std::string> names) {  // {}: results.nc only
    csv = std::move(names);
    return *this;
  }
  Column& over(std::vector<std::string> d) {
    dims = std::move(d);
    return *this;
  }
  Column& with_format(std::string f) {
    format = std::move(f);
    return *this;
  }
  Column& attribute(const std::string& key, nlohmann::json value) {
    attributes[key] = std::move(value);
    return *this;
  }
};

class Table {
 public:
  // file: the CSV file name ("": results.nc only); rows: the dimensions (name, length) whose every
  // combination is one CSV line; real_format: the CSV format of the real columns unless set per column.
  Table(std::string file, std::vector<std::pair<std::string, std::size_t>> rows, std::string real_format);

  // A dimension that is not a CSV row (vector components "xyz", bin edges).
  void add_dim(std::string name, std::size_t length);

  // Columns over all row dimensions (Column::over for others). The reference is valid until the next
  // column is added.
  Column& real(std::string name, std::string units, std::string long_name, std::vector<double> values);
  Column& integer(std::string name, std::string units, std::string long_name, std::vector<std::int64_t> values);
  // Integer codes 0, 1, ... with one word each (results.nc flag_values/flag_meanings, units "1").
  Column& flag(std::string name, std::string long_name, std::vector<std::string> words,
               std::vector<std::int64_t> values);

  const std::string& file() const { return file_; }
  const std::vector<Column>& columns() const { return columns_; }

  // std::logic_error when a column's values do not fill its dimensions or its CSV headers do not fit them.
  void write_csv(std::ostream& os) const;
  void add_to(Dataset& d) const;

 private:
  std::size_t length(const std::string& dim) const;
  std::string file_;
  std::vector<std::pair<std::string, std::size_t>> rows_, other_;
  std::string real_format_;
  std::vector<Column> columns_;
};

// Writes t.file() into `out` (atomically, OutputDir::write).
void write_csv(const OutputDir& out, const Table& t);

}  // namespace agglo::io
