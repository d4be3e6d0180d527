#include "agglo/io/ensemble_tables.hpp"

#include <string>

#include <fmt/format.h>

#include "agglo/io/sweep_table.hpp"

namespace agglo::io {

void write_ensemble_summary(const OutputDir& out, const std::vector<SummaryStat>& stats) {
  out.write("ensemble_summary.csv", [&](std::ostream& os) {
    os << "quantity,unit,mean,stderr,n\n";
    for (const auto& s : stats)
      os << fmt::format("{},{},{:.10g},{:.10g},{}\n", csv_field(s.quantity), csv_field(s.unit), s.value.mean,
                        s.value.standard_error, s.value.n);
  });
}

void write_ensemble_timeseries(const OutputDir& out, const Dataset& ensemble) {
  const Variable* time = ensemble.find("time");
  if (!time || time->integer) return;
  std::vector<const Variable*> cols;
  for (const auto& v : ensemble.variables) {
    const auto n = v.name.size();
    if (v.dims != std::vector<std::string>{"time"} || n < 5 || v.name.compare(n - 5, 5, "_mean") != 0) continue;
    const Variable* error = ensemble.find(v.name.substr(0, n - 5) + "_stderr");
    if (error) cols.insert(cols.end(), {&v, error});
  }
  out.write("ensemble_timeseries.csv", [&](std::ostream& os) {
    os << "t_s";
    for (const auto* c : cols) os << ',' << csv_field(c->name);
    os << '\n';
    for (std::size_t i = 0; i < time->size(); ++i) {
      os << fmt::format("{:.10g}", time->reals[i]);
      for (const auto* c : cols) os << fmt::format(",{:.10g}", c->reals[i]);
      os << '\n';
    }
  });
}

}  // namespace agglo::io
