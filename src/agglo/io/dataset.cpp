#include "agglo/io/dataset.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace agglo::io {

void Dataset::add_dim(const std::string& name, std::size_t length) {
  for (const auto& [n, len] : dims) {
    if (n != name) continue;
    if (len != length)
      throw std::logic_error(fmt::format("dataset: dimension {} redefined with length {} (was {})", name, length, len));
    return;
  }
  dims.emplace_back(name, length);
}

std::size_t Dataset::dim_length(const std::string& name) const {
  for (const auto& [n, len] : dims)
    if (n == name) return len;
  throw std::logic_error(fmt::format("dataset: dimension {} is not defined", name));
}

const Variable* Dataset::find(const std::string& name) const {
  for (const auto& v : variables)
    if (v.name == name) return &v;
  return nullptr;
}

namespace {
void check_shape(const Dataset& d, const Variable& v) {
  std::size_t n = 1;
  for (const auto& dim : v.dims) n *= d.dim_length(dim);
  if (n != v.size())
    throw std::logic_error(fmt::format("dataset: variable {} has {} values, its dimensions hold {}", v.name, v.size(), n));
  if (d.find(v.name)) throw std::logic_error(fmt::format("dataset: variable {} defined twice", v.name));
}
}  // namespace

Variable& Dataset::add(const std::string& name, std::vector<std::string> dims_of, std::string units,
                       std::string long_name, std::vector<double> values) {
  Variable v{name, std::move(dims_of), std::move(units), std::move(long_name), false, std::move(values), {}};
  check_shape(*this, v);
  variables.push_back(std::move(v));
  return variables.back();
}

Variable& Dataset::add_ints(const std::string& name, std::vector<std::string> dims_of, std::string units,
                            std::string long_name, std::vector<std::int64_t> values) {
  Variable v{name, std::move(dims_of), std::move(units), std::move(long_name), true, {}, std::move(values)};
  check_shape(*this, v);
  variables.push_back(std::move(v));
  return variables.back();
}

}  // namespace agglo::io
