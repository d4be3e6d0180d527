// agglo.sweep: any command over a grid of config values (run/sweep.hpp, as `agglo sweep`), on a worker
// thread like the command functions; the result's summary lists the cases with their summaries.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "agglo/run/ensemble_request.hpp"
#include "bindings.hpp"
#include "case.hpp"
#include "options.hpp"

namespace py = pybind11;

namespace agglo::python {

namespace {

// A swept value as TOML text: a str is taken as written (like the CLI's --values: a bare word is a
// string), anything else converted by toml_value.
std::string sweep_value(py::handle v) { return py::isinstance<py::str>(v) ? v.cast<std::string>() : toml_value(v); }

nlohmann::json value_json(const std::string& text) {
  const auto j = nlohmann::json::parse(text, nullptr, false);
  return j.is_discarded() ? nlohmann::json(text) : j;
}

nlohmann::json cases_json(const std::vector<run::SweepAxis>& axes, const run::SweepResult& res) {
  nlohmann::json cases = nlohmann::json::array();
  for (std::size_t i = 0; i < res.cases.size(); ++i) {
    nlohmann::json values = nlohmann::json::object();
    for (std::size_t k = 0; k < axes.size(); ++k) values[axes[k].key] = value_json(res.cases[i].values[k]);
    cases.push_back({{"index", res.cases[i].index}, {"values", values}, {"folder", res.cases[i].folder},
                     {"summary", res.summaries[i]}});
  }
  return cases;
}

// The points of a sweep with seeds: {"values": {key: value}, "members", "folder", "statistics", "stats": {q:
// {"mean", "stderr", "n"}}} in grid order.
nlohmann::json points_json(const std::vector<run::SweepAxis>& axes, const run::EnsembleResult& res) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < res.points.size(); ++i) {
    const auto& p = res.points[i];
    nlohmann::json values = nlohmann::json::object(), stats = nlohmann::json::object();
    for (std::size_t k = 0; k < p.values.size(); ++k) values[axes[k].key] = value_json(p.values[k]);
    for (const auto& s : p.stats)
      stats[s.quantity] = {{"mean", s.value.mean}, {"stderr", s.value.standard_error}, {"n", s.value.n}};
    out.push_back({{"values", values}, {"members", p.members}, {"folder", p.folder},
                   {"statistics", res.point_folders[i]}, {"stats", stats}});
  }
  return out;
}

Result sweep(const Case& c, const py::dict& params, const std::string& command, long long seeds,
             const RunOptions& o) {
  run::EnsembleRequest request{command, copy_of(c), {}, seeds, {}};
  for (auto [key, values] : params) {
    run::SweepAxis axis{py::str(key).cast<std::string>(), {}};
    for (auto v : py::reinterpret_borrow<py::iterable>(values)) axis.values.push_back(sweep_value(v));
    request.axes.push_back(std::move(axis));
  }
  const auto ctx = context_of(run::find_command(command), o);
  RunFolder folder(o.out);
  request.folder = folder.path();
  auto plan = run::plan_ensemble(std::move(request), ctx);  // every case validated before the folder is made
  auto r = run_released(
      [&](const run::RunContext& x) {
        const auto res = run::execute_ensemble(plan, x);
        run::CommandResult out;
        out.summary = {{"command", command}, {"cases", cases_json(plan.axes, res.runs)}};
        if (!plan.seeds.empty()) out.summary["points"] = points_json(plan.axes, res);
        out.data = res.runs.data;
        return out;
      },
      ctx, o.progress);
  return Result{"sweep", std::move(r.result.summary), 0, folder.user_path(), std::move(r.result.data),
                std::move(r.messages)};
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def(
      "sweep",
      [](const py::args& args, const py::kwargs& kwargs) {
        Arguments a("agglo.sweep", args, kwargs, {"case", "params"});
        const Case& c = case_of(a);
        const py::object params = a.take("params");
        if (!py::isinstance<py::dict>(params)) a.fail("params", params, "give a dict {dotted key: list of values}");
        const py::object command = a.take("command");
        if (!command.is_none() && !py::isinstance<py::str>(command))
          a.fail("command", command, "give a command name (agglo.command_names())");
        const long long seeds = a.integer("seeds", 1, 1, kNoLimit);
        const auto o = options_of(a, false);
        a.finish();
        return sweep(c, params.cast<py::dict>(), command.is_none() ? "acoustic" : command.cast<std::string>(), seeds, o);
      },
      R"(sweep(case, params, *, command="acoustic", seeds=1, out=None, threads=0, progress=None, format="csv,netcdf", resume=False, overwrite=False, max_steps=None, max_memory=None, max_output=None)

      R"(Runs `command` for every point of a grid of config values, cases in parallel (as `agglo sweep`).

  case     agglo.Case: the base case (not changed)
  params   dict {dotted key: list of values}, e.g. {"projectile.speed": [0.1, 0.2]}; several keys make a
           grid (last key fastest). A str value is TOML text as on the command line (a bare word is a string).
  command  the command run for each case (default "acoustic"; see command_names())
  seeds    N >= 2: every point runs N seeds (derived from the case's seed and the member index; member 0
           is the case's own seed), the seed being the grid's last axis; out also gets sweep_ensemble.csv
           and sweep_ensemble.nc with each point's scalar means and standard errors, and per point a folder
           point_<index>_<values> with the mean and standard error of every result (ensemble_summary.csv,
           ensemble_timeseries.csv, results.nc; docs/outputs.md) (default 1: one run per point)
  out, threads, progress, format, resume, overwrite, max_steps, max_memory, max_output: as for the
           command functions (no checkpoint);
  out gets sweep.csv and one folder per case.

Returns an agglo.Result whose summary is {"command": ..., "cases": [{"index", "values": {key: value},
"folder", "summary"}, ...]} in grid order (with seeds, also "points": [{"values": {key: value}, "members",
"folder" (member 0's), "statistics" (the point's folder), "stats": {quantity: {"mean", "stderr", "n"}}},
...]); its seed is 0 and its arrays
are the table of the cases (results.nc).)");
}

}  // namespace agglo::python
