#include "agglo/io/calibration_dataset.hpp"

#include <fmt/format.h>

#include "agglo/io/calibration_writers.hpp"
#include "agglo/io/config_units.hpp"
#include "agglo/io/dataset_scalars.hpp"

namespace agglo::io {

namespace {

void add_points(Dataset& d, const calibrate::Spec& spec, const calibrate::Result& r) {
  const std::size_t nd = spec.parameters.size(), nt = spec.targets.size();
  std::vector<std::int64_t> round;
  std::vector<std::vector<double>> x(nd), obs(nt), weight(nt);
  for (const auto& p : r.points) {
    round.push_back(p.round);
    for (std::size_t j = 0; j < nd; ++j) x[j].push_back(j < p.x.size() ? p.x[j] : 0.0);
    for (std::size_t k = 0; k < nt; ++k) {
      obs[k].push_back(k < p.observables.size() ? p.observables[k].value : 0.0);
      weight[k].push_back(k < p.robust_weight.size() ? p.robust_weight[k] : 0.0);
    }
  }
  add_int_column(d, "round", "point", "1", "mapping round of the run", round);
  for (std::size_t j = 0; j < nd; ++j)
    d.add(fmt::format("x{}", j), {"point"}, udunits_of_config_key(spec.parameters[j].key),
          "value of " + spec.parameters[j].key, x[j])
        .attributes["config_key"] = spec.parameters[j].key;
  for (std::size_t k = 0; k < nt; ++k) {
    d.add(fmt::format("obs{}", k), {"point"}, "m s-1", fmt::format("observable of target {} (NaN: none)", k), obs[k]);
    d.add(fmt::format("weight{}", k), {"point"}, "1", fmt::format("robustness weight of target {}", k), weight[k]);
  }
}

void add_surface(Dataset& d, const calibrate::Spec& spec, const calibrate::Result& r) {
  const std::size_t nd = spec.parameters.size(), nt = spec.targets.size();
  d.add_dim("surface_point", r.plot_u.size());
  for (std::size_t j = 0; j < nd; ++j) {
    std::vector<double> x;
    for (const auto& u : r.plot_u) x.push_back(spec.parameters[j].from_unit(u[j]));
    d.add(fmt::format("surface_x{}", j), {"surface_point"}, udunits_of_config_key(spec.parameters[j].key),
          "value of " + spec.parameters[j].key, x);
  }
  for (std::size_t k = 0; k < nt && k < r.plot_values.size(); ++k)
    if (r.plot_values[k].size() == r.plot_u.size())
      d.add(fmt::format("surrogate{}", k), {"surface_point"}, "m s-1", fmt::format("surrogate of target {}", k),
            r.plot_values[k]);
}

}  // namespace

Dataset calibration_dataset(const calibrate::Spec& spec, const calibrate::Result& r,
                            const std::vector<std::string>& case_files, const std::vector<std::string>& observables,
                            const std::vector<calibrate::Prediction>& predictions) {
  Dataset d;
  add_points(d, spec, r);
  add_surface(d, spec, r);
  const std::size_t nd = spec.parameters.size();
  if (r.best.size() == nd)
    add_column(d, "best", "parameter", "1", "fitted parameter values (units of x0, x1, ...)", r.best);
  if (r.feasible_lo.size() == nd && r.feasible_hi.size() == nd) {
    add_column(d, "feasible_lo", "parameter", "1", "feasible set, lower corner (units of x0, x1, ...)", r.feasible_lo);
    add_column(d, "feasible_hi", "parameter", "1", "feasible set, upper corner (units of x0, x1, ...)", r.feasible_hi);
  }
  add_scalars(d, calibration_json(spec, r, case_files, observables, predictions));
  return d;
}

}  // namespace agglo::io
