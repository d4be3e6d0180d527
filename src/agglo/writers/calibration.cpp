#include "agglo/writers/calibration.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "agglo/io/config_units.hpp"
#include "agglo/io/dataset_scalars.hpp"

namespace agglo::writers {

namespace {

nlohmann::json num(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json parameters_json(const calibrate::Spec& spec, const calibrate::Result& r) {
  auto a = nlohmann::json::array();
  for (std::size_t j = 0; j < spec.parameters.size(); ++j) {
    const auto& p = spec.parameters[j];
    a.push_back({{"key", p.key}, {"lower", p.lower}, {"upper", p.upper}, {"scale", p.log_scale ? "log" : "linear"},
                 {"best", r.best[j]}, {"sigma", num(r.sigma[j])},
                 {"feasible_lo", r.feasible ? num(r.feasible_lo[j]) : nullptr},
                 {"feasible_hi", r.feasible ? num(r.feasible_hi[j]) : nullptr}});
  }
  return a;
}

nlohmann::json targets_json(const calibrate::Spec& spec, const calibrate::Result& r,
                            const std::vector<std::string>& files, const std::vector<std::string>& observables) {
  auto a = nlohmann::json::array();
  for (std::size_t k = 0; k < spec.targets.size(); ++k) {
    const auto& t = spec.targets[k];
    nlohmann::json e{{"name", t.name},          {"case", files[k]},           {"observable", observables[k]},
                     {"value", t.value},        {"tolerance", t.tolerance},  {"predicted", num(r.predicted[k])},
                     {"predicted_residual", num(r.predicted[k] - t.value)}};
    e["local_scatter"] = num(r.local_scatter[k]);  // single runs near the best fit scatter this much
    std::size_t without = 0;
    for (const auto& p : r.points) without += std::isfinite(p.observables[k].value) ? 0 : 1;
    e["runs_without_value"] = without;  // e.g. no break-up up to the scan's highest speed
    if (!r.achieved.empty()) {
      e["achieved"] = num(r.achieved[k].value);
      e["residual"] = num(r.achieved[k].value - t.value);
      e["met"] = std::abs(r.achieved[k].value - t.value) <= t.tolerance;
      e["width"] = r.achieved[k].width > 0.0 ? num(r.achieved[k].width) : nullptr;
    }
    a.push_back(e);
  }
  return a;
}

nlohmann::json predictions_json(const std::vector<calibrate::Prediction>& predictions) {
  auto a = nlohmann::json::array();
  for (const auto& p : predictions) {
    double lo = INFINITY, hi = -INFINITY;
    auto pts = nlohmann::json::array();
    for (std::size_t i = 0; i < p.x.size(); ++i) {
      pts.push_back({{"x", p.x[i]}, {"value", num(p.values[i])}});
      if (std::isfinite(p.values[i])) {
        lo = std::min(lo, p.values[i]);
        hi = std::max(hi, p.values[i]);
      }
    }
    a.push_back({{"name", p.name}, {"at_best", num(p.values.empty() ? NAN : p.values[0])}, {"min", num(lo)},
                 {"max", num(hi)}, {"points", pts}});
  }
  return a;
}

}  // namespace

nlohmann::json calibration_json(const calibrate::Spec& spec, const calibrate::Result& r,
                                const std::vector<std::string>& files, const std::vector<std::string>& observables,
                                const std::vector<calibrate::Prediction>& predictions) {
  return {{"parameters", parameters_json(spec, r)},
          {"predictions", predictions_json(predictions)},
          {"targets", targets_json(spec, r, files, observables)},
          {"chi2", num(r.chi2)},
          {"feasible", r.feasible},
          {"feasible_points", r.feasible_points},
          {"feasible_extremes", r.feasible_extremes},
          {"fine_points", spec.fine_points},
          {"rounds", r.rounds},
          {"mapped_points", r.points.size()},
          {"sigma_from", spec.widths ? "width of p(v) at the best fit" : "target tolerances"}};
}

io::Table points_table(const calibrate::Spec& spec, const calibrate::Result& r) {
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
  io::Table t("calibration_points.csv", {{"point", r.points.size()}}, "{:.10g}");
  t.integer("round", "1", "mapping round of the run", round);
  for (std::size_t j = 0; j < nd; ++j) {
    const auto& key = spec.parameters[j].key;
    t.real(fmt::format("x{}", j), io::udunits_of_config_key(key), "value of " + key, x[j]).attribute("config_key", key);
  }
  for (std::size_t k = 0; k < nt; ++k) {
    t.real(fmt::format("obs{}", k), "m s-1", fmt::format("observable of target {} (NaN: none)", k), obs[k]);
    t.real(fmt::format("weight{}", k), "1", fmt::format("robustness weight of target {}", k), weight[k])
        .with_format("{:.4g}");
  }
  return t;
}

io::Table surface_table(const calibrate::Spec& spec, const calibrate::Result& r) {
  const std::size_t nd = spec.parameters.size(), nt = spec.targets.size();
  io::Table t("calibration_surface.csv", {{"surface_point", r.plot_u.size()}}, "{:.10g}");
  for (std::size_t j = 0; j < nd; ++j) {
    std::vector<double> x;
    for (const auto& u : r.plot_u) x.push_back(spec.parameters[j].from_unit(u[j]));
    const auto& key = spec.parameters[j].key;
    t.real(fmt::format("surface_x{}", j), io::udunits_of_config_key(key), "value of " + key, x)
        .header({fmt::format("x{}", j)});
  }
  for (std::size_t k = 0; k < nt && k < r.plot_values.size(); ++k)
    if (r.plot_values[k].size() == r.plot_u.size())
      t.real(fmt::format("surrogate{}", k), "m s-1", fmt::format("surrogate of target {}", k), r.plot_values[k]);
  return t;
}

void write_calibration(const OutputDir& out, const calibrate::Spec& spec, const calibrate::Result& r,
                       const std::vector<std::string>& files, const std::vector<std::string>& observables,
                       const std::vector<calibrate::Prediction>& predictions) {
  out.write_json("calibration.json", calibration_json(spec, r, files, observables, predictions));
  io::write_csv(out, points_table(spec, r));
  io::write_csv(out, surface_table(spec, r));
}

io::Dataset calibration_dataset(const calibrate::Spec& spec, const calibrate::Result& r,
                                const std::vector<std::string>& case_files,
                                const std::vector<std::string>& observables,
                                const std::vector<calibrate::Prediction>& predictions) {
  io::Dataset d;
  points_table(spec, r).add_to(d);
  surface_table(spec, r).add_to(d);
  const std::size_t nd = spec.parameters.size();
  if (r.best.size() == nd)
    io::add_column(d, "best", "parameter", "1", "fitted parameter values (units of x0, x1, ...)", r.best);
  if (r.feasible_lo.size() == nd && r.feasible_hi.size() == nd) {
    io::add_column(d, "feasible_lo", "parameter", "1", "feasible set, lower corner (units of x0, x1, ...)",
                   r.feasible_lo);
    io::add_column(d, "feasible_hi", "parameter", "1", "feasible set, upper corner (units of x0, x1, ...)",
                   r.feasible_hi);
  }
  io::add_scalars(d, calibration_json(spec, r, case_files, observables, predictions));
  return d;
}

}  // namespace agglo::writers
