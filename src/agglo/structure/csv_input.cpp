#include "agglo/structure/csv_input.hpp"

#include <array>
#include <charconv>
#include <sstream>

#include <fmt/format.h>

namespace agglo::structure {

namespace {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream s(line);
  while (std::getline(s, cell, ',')) {
    const auto b = cell.find_first_not_of(" \t\r"), e = cell.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
  }
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

constexpr std::array<const char*, 7> kColumns = {"x", "y", "z", "radius", "charge", "permittivity", "material"};

struct CsvContext {
  const std::string& source;
  const std::string& key;
  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw BuildError(key, fmt::format("{} line {}: {}", source, line, what));
  }
};

std::array<int, 7> column_positions(const std::vector<std::string>& header, const CsvContext& ctx, std::size_t line) {
  std::array<int, 7> pos;
  pos.fill(-1);
  for (std::size_t c = 0; c < header.size(); ++c)
    for (std::size_t k = 0; k < kColumns.size(); ++k)
      if (header[c] == kColumns[k]) pos[k] = static_cast<int>(c);
  for (std::size_t k = 0; k < 4; ++k)
    if (pos[k] < 0)
      ctx.fail(line, fmt::format("the header has no column '{}' (needed: x, y, z, radius; optional: charge, "
                                 "permittivity, material)",
                                 kColumns[k]));
  return pos;
}

double number_at(const std::vector<std::string>& cells, int c, const CsvContext& ctx, std::size_t line) {
  if (c >= static_cast<int>(cells.size())) ctx.fail(line, fmt::format("has {} values, fewer than the header", cells.size()));
  const std::string& t = cells[static_cast<std::size_t>(c)];
  double v = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size() || t.empty())
    ctx.fail(line, fmt::format("'{}' in column {} is not a number", t, c + 1));
  return v;
}

// A text cell (a material name): not empty.
std::string text_at(const std::vector<std::string>& cells, int c, const CsvContext& ctx, std::size_t line) {
  if (c >= static_cast<int>(cells.size()) || cells[static_cast<std::size_t>(c)].empty())
    ctx.fail(line, fmt::format("has no value in column {} (material)", c + 1));
  return cells[static_cast<std::size_t>(c)];
}

}  // namespace

Aggregate read_aggregate_csv(std::istream& in, const std::string& source, const std::string& key) {
  const CsvContext ctx{source, key};
  Aggregate a;
  std::array<int, 7> pos{};
  bool have_header = false;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    const auto cells = split_csv_line(line);
    if (!have_header) {
      pos = column_positions(cells, ctx, n);
      have_header = true;
      continue;
    }
    if (a.size() >= kMaxFilePrimaries)
      ctx.fail(n, fmt::format("more than {} primaries (the O(N^2) contact check's limit)", kMaxFilePrimaries));
    a.add({number_at(cells, pos[0], ctx, n), number_at(cells, pos[1], ctx, n), number_at(cells, pos[2], ctx, n)},
          number_at(cells, pos[3], ctx, n));
    if (pos[4] >= 0) a.charge.push_back(number_at(cells, pos[4], ctx, n));
    if (pos[5] >= 0) a.permittivity.push_back(number_at(cells, pos[5], ctx, n));
    if (pos[6] >= 0) a.material.push_back(text_at(cells, pos[6], ctx, n));
  }
  if (!have_header) ctx.fail(1, "empty file: expected a header line x,y,z,radius");
  return a;
}

}  // namespace agglo::structure
