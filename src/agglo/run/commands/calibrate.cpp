// agglo calibrate: fit one or two keys of impact cases so that their v_crit / v50 hit target values
// (calibrate/calibration.hpp for the method, docs/calibrate.md). Every run of a map is a job of the
// ensemble runner (all cores, journaled: --resume repeats only the missing runs); inside a job the
// vcrit bisection or the break-up curve runs on one thread.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/core/settings_calibrate.hpp"
#include "agglo/impact/breakup.hpp"
#include "agglo/impact/estimate.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/vcrit.hpp"
#include "agglo/run/calibrate_case.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/run/ensemble.hpp"
#include "agglo/run/impact_ensemble.hpp"
#include "agglo/run/journal.hpp"
#include "agglo/writers/calibration.hpp"

namespace agglo::run {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One observable at one parameter point: {"value": v, "width": w} (value null when undefined).
nlohmann::json observe(const CalibrateCase& c, const CalibrationTarget& t, const std::vector<double>& x, bool widths,
                       const JobContext& job) {
  Config cfg = target_config(c, t, x);
  auto ic = impact::parse_impact_case(cfg);
  ic.vcrit.top_down = true;  // only v_crit is kept: the runs below its bracket are not needed (vcrit.hpp)
  const auto relaxed = impact::relaxed_agglomerate(ic);
  const EnsembleOptions inner{1, nullptr, job.cancel, nullptr, "calibrate"};
  nlohmann::json r{{"value", nullptr}, {"width", 0.0}};
  if (t.observable == "v_crit") {
    const auto v = impact::find_vcrit(ic.vcrit, speed_batch(ic, relaxed, inner));
    r["value"] = v.v_crit;
    r["runs"] = v.runs.size();
  }
  if (t.observable == "v50" || widths) {
    const auto b = impact::breakup_probability(ic.breakup, ic.projectile.offset_radii, impact_batch(ic, relaxed, inner));
    if (t.observable == "v50" && b.v50 > 0.0) r["value"] = b.v50;
    if (b.v10 > 0.0 && b.v90 > 0.0) r["width"] = (b.v90 - b.v10) / 2.563;  // normal p(v): v90 - v10 = 2.563 sigma
  }
  return r;
}

// A run the model cannot complete (e.g. no break-up up to the scan's highest speed) is a point without a
// value: the surrogate skips it and calibration.json counts it; interruptions and bad input still stop the fit.
nlohmann::json observe_or_note(const CalibrateCase& c, const CalibrationTarget& t, const std::vector<double>& x,
                               bool widths, const JobContext& job) {
  try {
    return observe(c, t, x, widths, job);
  } catch (const NumericalError& e) {
    return {{"value", nullptr}, {"width", 0.0}, {"failed", e.what()}};
  }
}

// One observable of one case at one parameter point: the job's journal key ("target=k case=<hash> x=...;[
// widths]", "prediction=k case=<hash> x=...;") and the case it runs. The key carries the hash of the resolved
// case, so that a resumed fit reuses every run whose case is unchanged (e.g. after [[prediction]] tables were
// added or calibrate.predict changed).
struct Request {
  std::string kind;  // "target" or "prediction"
  std::size_t index = 0;
  const CalibrationTarget* target = nullptr;
  std::vector<double> x;
  bool widths = false;
  std::string key() const {
    std::string k = fmt::format("{}={} case={} x=", kind, index, hash_hex(target->observable + "\n" + target->resolved));
    for (double v : x) k += fmt::format("{};", v);  // shortest round-trip digits
    return widths ? k + " widths" : k;
  }
};

// Runs the requests as journaled jobs of the ensemble runner; observations in request order.
std::vector<calibrate::Observation> run_requests(const CalibrateCase& c, const std::vector<Request>& requests,
                                                 Journal& journal, const RunContext& ctx, std::string_view label) {
  std::vector<Job> jobs;
  for (const auto& q : requests)
    jobs.push_back({q.key(), [&c, &q](const JobContext& j) { return observe_or_note(c, *q.target, q.x, q.widths, j); }});
  const auto outcomes = run_jobs(jobs, {ctx.threads, &journal, ctx.cancel, &ctx.report(), std::string(label)});
  rethrow_first_error(outcomes, &jobs);
  std::vector<calibrate::Observation> obs;
  for (const auto& o : outcomes)
    obs.push_back({o.result["value"].is_null() ? kNaN : o.result["value"].get<double>(), o.result["width"].get<double>()});
  return obs;
}

calibrate::Evaluator evaluator(const CalibrateCase& c, Journal& journal, const RunContext& ctx) {
  return [&c, &journal, &ctx](const std::vector<std::vector<double>>& points, bool widths) {
    std::vector<Request> requests;
    for (const auto& x : points)
      for (std::size_t k = 0; k < c.targets.size(); ++k) requests.push_back({"target", k, &c.targets[k], x, widths});
    const auto flat = run_requests(c, requests, journal, ctx, "calibrate");
    std::vector<std::vector<calibrate::Observation>> obs(points.size());
    for (std::size_t i = 0; i < flat.size(); ++i) obs[i / c.targets.size()].push_back(flat[i]);
    return obs;
  };
}

// Every [[prediction]] at the best fit and (calibrate.predict = "range") at the feasible set's extreme points,
// journaled like the maps; none for calibrate.predict = "none".
std::vector<calibrate::Prediction> predict(const CalibrateCase& c, const calibrate::Result& res, Journal& journal,
                                           const RunContext& ctx) {
  if (c.predict == "none") return {};
  std::vector<std::vector<double>> points{res.best};
  if (c.predict == "range")
    for (const auto& x : res.feasible_extremes)
    if (std::find(points.begin(), points.end(), x) == points.end()) points.push_back(x);
  std::vector<Request> requests;
  for (std::size_t k = 0; k < c.predictions.size(); ++k)
    for (const auto& x : points) requests.push_back({"prediction", k, &c.predictions[k], x, false});
  const auto flat = run_requests(c, requests, journal, ctx, "predictions");
  std::vector<calibrate::Prediction> out;
  for (std::size_t k = 0; k < c.predictions.size(); ++k) {
    calibrate::Prediction p{fmt::format("{} {}", c.predictions[k].file.stem().string(), c.predictions[k].observable),
                            points, {}};
    for (std::size_t i = 0; i < points.size(); ++i) p.values.push_back(flat[k * points.size() + i].value);
    out.push_back(p);
  }
  return out;
}

// Bytes one observation adds to the output (its journal line and its row of the map files; 2 KiB bounds
// both), and the calibration's fixed files (calibration.json, the surrogate grid, run.json).
constexpr double kObservationBytes = 2048.0;
constexpr double kCalibrationFilesBytes = 1024.0 * 1024.0;

// The cost of one observation of `t` (observe(): a vcrit search for v_crit, a break-up curve for v50 or
// `widths`, each on one thread and `threads` jobs at a time) at the costliest corner of the parameter box.
Estimate observation_cost(const CalibrateCase& c, const CalibrationTarget& t, bool widths, int threads) {
  Estimate worst;
  const std::size_t d = c.spec.parameters.size();
  for (std::size_t corner = 0; corner < (std::size_t{1} << d); ++corner) {
    std::vector<double> x;
    for (std::size_t j = 0; j < d; ++j)
      x.push_back((corner >> j) & 1U ? c.spec.parameters[j].upper : c.spec.parameters[j].lower);
    Config cfg = target_config(c, t, x);
    const auto ic = impact::parse_impact_case(cfg);
    Estimate e;
    if (t.observable == "v_crit") e = impact::vcrit_estimate(ic, threads);
    if (t.observable == "v50" || widths) {
      const Estimate b = impact::breakup_estimate(ic, threads);
      add_to(e.steps, b.steps.value, b.steps.keys);
      e.memory = e.memory.value >= b.memory.value ? e.memory : b.memory;
    }
    if (e.steps.value >= worst.steps.value) worst.steps = e.steps;
    if (e.memory.value >= worst.memory.value) worst.memory = e.memory;
  }
  return worst;
}

// Points where each [[prediction]] is run: the best fit, and with predict = "range" at most two extreme
// points of the feasible set per parameter.
double prediction_points(const CalibrateCase& c) {
  if (c.predict == "none") return 0.0;
  return c.predict == "best" ? 1.0 : 1.0 + 2.0 * static_cast<double>(c.spec.parameters.size());
}

// Every observation of the fit: the maps and the check per target, then the predictions; the memory of
// the costliest observation, `threads` at a time.
Estimate calibrate_estimate(const CalibrateCase& c, int threads) {
  const auto& f = settings::calibrate_settings().fit;
  Estimate e;
  add_to(e.steps, 0.0, {std::string(f.grid_points.dotted()), std::string(f.refine_rounds.dotted()),
                        std::string(f.refine_points.dotted())});
  double observations = 0.0;
  auto add = [&](const Estimate& one, double times) {
    add_to(e.steps, times * one.steps.value, one.steps.keys);
    if (one.memory.value > e.memory.value) e.memory = one.memory;
    observations += times;
  };
  const double maps = calibrate::map_points(c.spec), check = c.spec.check ? 1.0 : 0.0;
  for (const auto& t : c.targets) {
    add(observation_cost(c, t, false, threads), maps + (c.spec.widths ? 0.0 : check));
    if (c.spec.widths) add(observation_cost(c, t, true, threads), check);
  }
  for (const auto& t : c.predictions) add(observation_cost(c, t, false, threads), prediction_points(c));
  add_to(e.output, observations * kObservationBytes + kCalibrationFilesBytes, {std::string(f.grid_points.dotted())});
  return e;
}

class Calibrate final : public Command {
 public:
  std::string_view name() const override { return "calibrate"; }
  std::string_view help() const override {
    return "Fit one or two keys of impact cases so that their v_crit / v50 hit target values";
  }
  bool resumable() const override { return true; }
  void parse(Config& cfg) const override { (void)parse_calibrate_case(cfg); }
  // Every vcrit search and break-up curve of the fit, each bounded as by vcrit and breakup.
  Estimate estimate(Config& cfg, const RunContext& ctx) const override {
    return calibrate_estimate(parse_calibrate_case(cfg), ctx.thread_count());
  }
  // Its jobs are impact runs: the rate of run/commands/impact_command.hpp.
  double seconds_per_step(Config&) const override { return 2e-8; }

  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    const CalibrateCase c = parse_calibrate_case(cfg);
    Journal journal(out.file("journal.jsonl"), hash_hex("calibrate 2"), ctx.resume);  // cases: in the job keys
    calibrate::Result res;
    try {
      res = calibrate::calibrate(c.spec, evaluator(c, journal, ctx));
    } catch (const calibrate::UnreachableTarget& e) {
      const auto& t = settings::calibrate_settings().target;
      t.value.reject(t.t.elements(cfg.root())[e.target], e.what());
    }
    std::vector<std::string> files, observables;
    for (const auto& t : c.targets) {
      files.push_back(t.file.filename().string());
      observables.push_back(t.observable);
    }
    const auto predictions = predict(c, res, journal, ctx);
    if (ctx.formats.csv) writers::write_calibration(out, c.spec, res, files, observables, predictions);
    CommandResult r;
    r.data = std::make_shared<const io::Dataset>(writers::calibration_dataset(c.spec, res, files, observables, predictions));
    r.summary = {{"chi2", res.chi2}, {"feasible", res.feasible}, {"mapped_points", res.points.size()}};
    for (std::size_t j = 0; j < res.best.size(); ++j) r.summary[c.spec.parameters[j].key] = res.best[j];
    r.plot_script = "plot_calibration.py";
    std::string line = "calibrate: best";
    for (std::size_t j = 0; j < res.best.size(); ++j) line += fmt::format(" {} = {:.5g}", c.spec.parameters[j].key, res.best[j]);
    ctx.report().info(line + fmt::format(" (chi2 {:.3g}, {} runs, {})", res.chi2, res.points.size(),
                                         res.feasible ? "every target met" : "no point meets every target"));
    return r;
  }
};

}  // namespace

const Command& calibrate_command() {
  static const Calibrate c;
  return c;
}

}  // namespace agglo::run
