#include "agglo/io/ensemble_stats.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "agglo/io/dataset_scalars.hpp"
#include "agglo/io/sweep_table.hpp"

namespace agglo::io {

MeanStderr mean_stderr(const std::vector<double>& x) {
  MeanStderr r;
  r.n = x.size();
  if (x.empty()) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(), 0};
  double sum = 0.0;
  for (double v : x) sum += v;
  r.mean = sum / static_cast<double>(r.n);
  if (r.n < 2) {
    r.standard_error = std::numeric_limits<double>::quiet_NaN();
    return r;
  }
  double squares = 0.0;
  for (double v : x) squares += (v - r.mean) * (v - r.mean);
  r.standard_error = std::sqrt(squares / (static_cast<double>(r.n - 1) * static_cast<double>(r.n)));
  return r;
}

namespace {

bool is_coordinate(const Variable& v) { return v.dims.size() == 1 && v.dims[0] == v.name; }

bool has_coordinates(const Dataset& d, const Variable& v) {
  return std::all_of(v.dims.begin(), v.dims.end(), [&](const std::string& dim) {
    const Variable* c = d.find(dim);
    return c && is_coordinate(*c);
  });
}

double value_at(const Variable& v, std::size_t i) {
  return v.integer ? static_cast<double>(v.ints[i]) : v.reals[i];
}

bool same_values(const Variable& a, const Variable& b) {
  if (a.integer != b.integer || a.dims != b.dims || a.size() != b.size()) return false;
  if (a.integer) return a.ints == b.ints;
  for (std::size_t i = 0; i < a.reals.size(); ++i)
    if (std::bit_cast<std::uint64_t>(a.reals[i]) != std::bit_cast<std::uint64_t>(b.reals[i])) return false;
  return true;
}

// The coordinate variables of member 0 that every member has, bitwise the same.
std::vector<std::string> common_coordinates(const std::vector<Dataset>& members) {
  std::vector<std::string> names;
  for (const auto& v : members[0].variables) {
    if (!is_coordinate(v)) continue;
    if (std::all_of(members.begin(), members.end(), [&](const Dataset& m) {
          const Variable* w = m.find(v.name);
          return w && same_values(v, *w);
        }))
      names.push_back(v.name);
  }
  return names;
}

// Every member's `name` on the dims of `first`, or an empty list when a member lacks it.
std::vector<const Variable*> member_variables(const std::vector<Dataset>& members, const Variable& first) {
  std::vector<const Variable*> vs;
  for (const auto& m : members) {
    const Variable* w = m.find(first.name);
    if (!w || w->dims != first.dims || w->size() != first.size()) return {};
    vs.push_back(w);
  }
  return vs;
}

void add_statistics(Dataset& out, const Variable& first, const std::vector<const Variable*>& vs) {
  std::vector<double> mean(first.size()), error(first.size()), x(vs.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    for (std::size_t k = 0; k < vs.size(); ++k) x[k] = value_at(*vs[k], i);
    const auto s = mean_stderr(x);
    mean[i] = s.mean;
    error[i] = s.standard_error;
  }
  nlohmann::json attrs = first.attributes;
  attrs.erase("flag_values");
  attrs.erase("flag_meanings");
  out.add(first.name + "_mean", first.dims, first.units, "mean over the members: " + first.long_name, std::move(mean))
      .attributes = attrs;
  out.add(first.name + "_stderr", first.dims, first.units, "standard error of the mean: " + first.long_name,
          std::move(error))
      .attributes = attrs;
}

}  // namespace

Dataset labelled_part(const Dataset& d) {
  Dataset out;
  for (const auto& v : d.variables) {
    if (!has_coordinates(d, v)) continue;
    for (const auto& dim : v.dims) out.add_dim(dim, d.dim_length(dim));
    out.variables.push_back(v);
  }
  out.attributes = d.attributes;
  return out;
}

Dataset ensemble_dataset(const std::vector<Dataset>& members) {
  if (members.empty()) throw std::invalid_argument("ensemble_dataset: no members");
  const auto coords = common_coordinates(members);
  auto aligned = [&](const Variable& v) {
    return std::all_of(v.dims.begin(), v.dims.end(),
                       [&](const std::string& dim) { return std::count(coords.begin(), coords.end(), dim) > 0; });
  };
  Dataset out;
  std::string skipped;
  for (const auto& v : members[0].variables) {
    const auto vs = member_variables(members, v);
    if (is_coordinate(v) && aligned(v)) {
      out.add_dim(v.name, v.size());
      out.variables.push_back(v);
    } else if (!is_coordinate(v) && aligned(v) && !vs.empty()) {
      for (const auto& dim : v.dims) out.add_dim(dim, members[0].dim_length(dim));
      add_statistics(out, v, vs);
    } else {
      skipped += (skipped.empty() ? "" : " ") + v.name;
    }
  }
  if (!skipped.empty()) out.attributes["not_averaged"] = skipped;
  return out;
}

std::vector<SummaryStat> summary_stats(const std::vector<nlohmann::json>& summaries) {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;
  for (const auto& s : summaries) {
    std::vector<std::pair<std::string, double>> flat;
    flatten_scalars(s, "", flat);
    for (const auto& [k, x] : flat) {
      auto it = std::find(names.begin(), names.end(), k);
      if (it == names.end()) {
        names.push_back(k);
        values.emplace_back();
        it = names.end() - 1;
      }
      if (std::isfinite(x)) values[static_cast<std::size_t>(it - names.begin())].push_back(x);
    }
  }
  std::vector<SummaryStat> out;
  for (std::size_t i = 0; i < names.size(); ++i) out.push_back({names[i], units_of_key(names[i]), mean_stderr(values[i])});
  return out;
}

}  // namespace agglo::io
