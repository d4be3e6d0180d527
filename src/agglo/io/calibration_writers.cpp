#include "agglo/io/calibration_writers.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace agglo::io {

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

void write_calibration(const OutputDir& out, const calibrate::Spec& spec, const calibrate::Result& r,
                       const std::vector<std::string>& files, const std::vector<std::string>& observables,
                       const std::vector<calibrate::Prediction>& predictions) {
  out.write_json("calibration.json", calibration_json(spec, r, files, observables, predictions));
  const std::size_t d = spec.parameters.size(), nt = spec.targets.size();
  out.write("calibration_points.csv", [&](std::ostream& o) {
    o << "round";
    for (std::size_t j = 0; j < d; ++j) o << ",x" << j;
    for (std::size_t k = 0; k < nt; ++k) o << ",obs" << k << ",weight" << k;
    o << "\n";
    for (const auto& p : r.points) {
      o << p.round;
      for (double x : p.x) o << fmt::format(",{:.10g}", x);
      for (std::size_t k = 0; k < nt; ++k) o << fmt::format(",{:.10g},{:.4g}", p.observables[k].value, p.robust_weight[k]);
      o << "\n";
    }
  });
  out.write("calibration_surface.csv", [&](std::ostream& o) {
    for (std::size_t j = 0; j < d; ++j) o << (j ? "," : "") << "x" << j;
    for (std::size_t k = 0; k < nt; ++k) o << ",surrogate" << k;
    o << "\n";
    for (std::size_t i = 0; i < r.plot_u.size(); ++i) {
      for (std::size_t j = 0; j < d; ++j) o << (j ? "," : "") << fmt::format("{:.10g}", spec.parameters[j].from_unit(r.plot_u[i][j]));
      for (std::size_t k = 0; k < nt; ++k) o << fmt::format(",{:.10g}", r.plot_values[k][i]);
      o << "\n";
    }
  });
}

}  // namespace agglo::io
