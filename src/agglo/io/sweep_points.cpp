#include "agglo/io/sweep_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "agglo/io/dataset_scalars.hpp"
#include "agglo/io/sweep_dataset.hpp"
#include "agglo/io/sweep_table.hpp"

namespace agglo::io {

namespace {

// The union of the points' quantities in first-seen order.
std::vector<std::string> quantities(const std::vector<SweepPoint>& points) {
  std::vector<std::string> names;
  for (const auto& p : points)
    for (const auto& s : p.stats)
      if (std::find(names.begin(), names.end(), s.quantity) == names.end()) names.push_back(s.quantity);
  return names;
}

const SummaryStat* stat_of(const SweepPoint& p, const std::string& q) {
  auto it = std::find_if(p.stats.begin(), p.stats.end(), [&](const SummaryStat& s) { return s.quantity == q; });
  return it == p.stats.end() ? nullptr : &*it;
}

}  // namespace

void write_sweep_points(const OutputDir& out, const std::vector<std::string>& keys,
                        const std::vector<SweepPoint>& points) {
  const auto names = quantities(points);
  out.write("sweep_ensemble.csv", [&](std::ostream& os) {
    os << "index";
    for (const auto& k : keys) os << ',' << csv_field(k);
    os << ",members,case";
    for (const auto& q : names) os << ',' << csv_field(q + "_mean") << ',' << csv_field(q + "_stderr");
    os << '\n';
    for (std::size_t i = 0; i < points.size(); ++i) {
      os << i;
      for (const auto& v : points[i].values) os << ',' << csv_field(v);
      os << ',' << points[i].members << ',' << csv_field(points[i].folder);
      for (const auto& q : names) {
        const auto* s = stat_of(points[i], q);
        if (s) os << fmt::format(",{:.10g},{:.10g}", s->value.mean, s->value.standard_error);
        else os << ",,";
      }
      os << '\n';
    }
  });
}

Dataset sweep_points_dataset(const std::vector<std::string>& keys, const std::vector<SweepPoint>& points) {
  Dataset d;
  std::vector<std::int64_t> index, members;
  for (std::size_t i = 0; i < points.size(); ++i) {
    index.push_back(static_cast<std::int64_t>(i));
    members.push_back(static_cast<std::int64_t>(points[i].members));
  }
  add_int_column(d, "point", "point", "1", "point index (sweep_ensemble.csv index)", index);
  std::vector<std::vector<std::string>> values;
  for (const auto& p : points) values.push_back(p.values);
  add_key_columns(d, "point", keys, values);
  d.add_ints("members", {"point"}, "1", "seeds averaged at the point", members);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& q : quantities(points)) {
    std::vector<double> mean(points.size(), nan), error(points.size(), nan);
    for (std::size_t i = 0; i < points.size(); ++i)
      if (const auto* s = stat_of(points[i], q)) {
        mean[i] = s->value.mean;
        error[i] = s->value.standard_error;
      }
    d.add(netcdf_name(q + "_mean"), {"point"}, units_of_key(q), "mean over the seeds of " + q, mean);
    d.add(netcdf_name(q + "_stderr"), {"point"}, units_of_key(q), "standard error of the mean of " + q, error);
  }
  return d;
}

}  // namespace agglo::io
