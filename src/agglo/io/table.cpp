#include "agglo/io/table.hpp"

#include <functional>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

namespace agglo::io {

Table::Table(std::string file, std::vector<std::pair<std::string, std::size_t>> rows, std::string real_format)
    : file_(std::move(file)), rows_(std::move(rows)), real_format_(std::move(real_format)) {}

void Table::add_dim(std::string name, std::size_t length) { other_.emplace_back(std::move(name), length); }

std::size_t Table::length(const std::string& dim) const {
  for (const auto* list : {&rows_, &other_})
    for (const auto& [n, len] : *list)
      if (n == dim) return len;
  throw std::logic_error(fmt::format("table {}: dimension {} is not defined", file_, dim));
}

Column& Table::real(std::string name, std::string units, std::string long_name, std::vector<double> values) {
  Column c;
  c.name = std::move(name);
  for (const auto& r : rows_) c.dims.push_back(r.first);
  c.units = std::move(units);
  c.long_name = std::move(long_name);
  c.csv = {c.name};
  c.format = real_format_;
  c.reals = std::move(values);
  columns_.push_back(std::move(c));
  return columns_.back();
}

Column& Table::integer(std::string name, std::string units, std::string long_name, std::vector<std::int64_t> values) {
  Column& c = real(std::move(name), std::move(units), std::move(long_name), {});
  c.integer = true;
  c.format = "{}";
  c.ints = std::move(values);
  return c;
}

Column& Table::flag(std::string name, std::string long_name, std::vector<std::string> words,
                    std::vector<std::int64_t> values) {
  Column& c = integer(std::move(name), "1", std::move(long_name), std::move(values));
  std::string meanings;
  nlohmann::json codes = nlohmann::json::array();
  for (std::size_t k = 0; k < words.size(); ++k) {
    meanings += (k ? " " : "") + words[k];
    codes.push_back(k);
  }
  c.attributes = {{"flag_values", codes}, {"flag_meanings", meanings}};
  c.labels = std::move(words);
  return c;
}

namespace {

// Where a CSV column finds its values: offset = sum over row dims of index * stride + component * comp_stride.
struct CsvSource {
  const Column* column;
  std::vector<std::size_t> row_stride;  // per row dimension (0: the column does not vary along it)
  std::size_t comp_stride = 0;
  std::size_t components = 1;
};

CsvSource source(const Column& c, const std::vector<std::pair<std::string, std::size_t>>& rows,
                 const std::function<std::size_t(const std::string&)>& length, const std::string& file) {
  CsvSource s{&c, std::vector<std::size_t>(rows.size(), 0)};
  std::size_t stride = 1, size = c.integer ? c.ints.size() : c.reals.size();
  bool component = false;
  for (auto d = c.dims.rbegin(); d != c.dims.rend(); ++d) {
    std::size_t r = 0;
    while (r < rows.size() && rows[r].first != *d) ++r;
    if (r < rows.size()) {
      s.row_stride[r] = stride;
    } else if (!component && d == c.dims.rbegin()) {
      component = true;
      s.comp_stride = stride;
      s.components = length(*d);
    } else {
      throw std::logic_error(fmt::format("table {}: column {} spreads over dimension {}, not its last", file, c.name, *d));
    }
    stride *= length(*d);
  }
  if (stride != size || s.components != c.csv.size())
    throw std::logic_error(fmt::format("table {}: column {} has {} values and {} CSV headers, its dimensions hold {} "
                                       "and {} components", file, c.name, size, c.csv.size(), stride, s.components));
  return s;
}

void append(fmt::memory_buffer& buf, const Column& c, std::size_t at) {
  if (!c.integer) {
    fmt::format_to(std::back_inserter(buf), fmt::runtime(c.format), c.reals[at]);
  } else if (c.labels.empty()) {
    fmt::format_to(std::back_inserter(buf), fmt::runtime(c.format), c.ints[at]);
  } else {
    const auto& word = c.labels.at(static_cast<std::size_t>(c.ints[at]));
    buf.append(word.data(), word.data() + word.size());
  }
}

}  // namespace

void Table::write_csv(std::ostream& os) const {
  std::vector<CsvSource> cols;
  std::string header;
  for (const auto& c : columns_) {
    if (c.csv.empty()) continue;
    cols.push_back(source(c, rows_, [this](const std::string& d) { return length(d); }, file_));
    for (const auto& h : c.csv) header += (header.empty() ? "" : ",") + h;
  }
  os << header << '\n';
  std::size_t lines = 1;
  for (const auto& r : rows_) lines *= r.second;
  std::vector<std::size_t> index(rows_.size(), 0);
  fmt::memory_buffer buf;
  for (std::size_t line = 0; line < lines; ++line) {
    buf.clear();
    bool first = true;
    for (const auto& s : cols) {
      std::size_t at = 0;
      for (std::size_t r = 0; r < index.size(); ++r) at += index[r] * s.row_stride[r];
      for (std::size_t k = 0; k < s.components; ++k, first = false) {
        if (!first) buf.push_back(',');
        append(buf, *s.column, at + k * s.comp_stride);
      }
    }
    buf.push_back('\n');
    os.write(buf.data(), static_cast<std::streamsize>(buf.size()));
    for (std::size_t r = index.size(); r-- > 0;) {  // next combination, innermost dimension fastest
      if (++index[r] < rows_[r].second) break;
      index[r] = 0;
    }
  }
}

void Table::add_to(Dataset& d) const {
  for (const auto* list : {&rows_, &other_})
    for (const auto& [n, len] : *list) d.add_dim(n, len);
  auto add = [&d](const Column& c) {
    Variable& v = c.integer ? d.add_ints(c.name, c.dims, c.units, c.long_name, c.ints)
                            : d.add(c.name, c.dims, c.units, c.long_name, c.reals);
    v.attributes = c.attributes;
  };
  auto coordinate = [](const Column& c) { return c.dims.size() == 1 && c.dims[0] == c.name; };
  for (const auto& c : columns_)
    if (coordinate(c)) add(c);
  for (const auto& c : columns_)
    if (!coordinate(c)) add(c);
}

void write_csv(const OutputDir& out, const Table& t) {
  out.write(t.file(), [&](std::ostream& os) { t.write_csv(os); });
}

}  // namespace agglo::io
