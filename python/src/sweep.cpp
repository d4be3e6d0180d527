// agglo.sweep: any command over a grid of config values (run/sweep.hpp, as `agglo sweep`), on a worker
// thread like the command functions; the result's summary lists the cases with their summaries.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "agglo/run/sweep.hpp"
#include "agglo/run/sweep_seeds.hpp"
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

// run.json's details, as the CLI writes them.
nlohmann::json details_of(const std::vector<run::SweepAxis>& axes, const std::string& command) {
  nlohmann::json keys = nlohmann::json::array(), lists = nlohmann::json::array();
  for (const auto& a : axes) {
    keys.push_back(a.key);
    std::string joined;
    for (const auto& v : a.values) joined += (joined.empty() ? "" : ",") + v;
    lists.push_back(joined);
  }
  return {{"param", axes.size() == 1 ? keys[0] : keys},
          {"values", axes.size() == 1 ? nlohmann::json(axes[0].values) : lists},
          {"command", command}};
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

// The points of a sweep with seeds: {"values": {key: value}, "members", "folder", "stats": {q: {"mean",
// "stderr", "n"}}} in grid order.
nlohmann::json points_json(const std::vector<run::SweepAxis>& axes, const std::vector<io::SweepPoint>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : points) {
    nlohmann::json values = nlohmann::json::object(), stats = nlohmann::json::object();
    for (std::size_t k = 0; k < p.values.size(); ++k) values[axes[k].key] = value_json(p.values[k]);
    for (const auto& s : p.stats)
      stats[s.quantity] = {{"mean", s.value.mean}, {"stderr", s.value.standard_error}, {"n", s.value.n}};
    out.push_back({{"values", values}, {"members", p.members}, {"folder", p.folder}, {"stats", stats}});
  }
  return out;
}

Result sweep(const Case& c, const py::dict& params, const std::string& command, long long seeds,
             const RunOptions& o) {
  const auto& cmd = run::find_command(command);
  std::vector<run::SweepAxis> axes;
  for (auto [key, values] : params) {
    run::SweepAxis axis{py::str(key).cast<std::string>(), {}};
    for (auto v : py::reinterpret_borrow<py::iterable>(values)) axis.values.push_back(sweep_value(v));
    axes.push_back(std::move(axis));
  }
  Config base = copy_of(c);
  auto details = details_of(axes, command);  // the user's axes, as the CLI records them
  if (seeds != 1) axes = run::with_seed_axis(cmd, base, std::move(axes), seeds);
  auto plan = run::plan_sweep(cmd, base, axes);  // every case validated before the folder is made
  const auto ctx = context_of(cmd, o);
  RunFolder folder(o.out);
  auto r = run_released(
      [&](const run::RunContext& x) {
        run::CommandResult out;
        if (seeds == 1) {
          const auto res = run::execute_sweep(cmd, base, axes, plan, folder.path(), x, details);
          out.summary = {{"command", command}, {"cases", cases_json(axes, res)}};
          out.data = res.data;
          return out;
        }
        details["seeds"] = seeds;
        const auto res = run::execute_seeded_sweep(cmd, base, axes, plan, folder.path(), x, details);
        out.summary = {{"command", command}, {"cases", cases_json(axes, res.runs)}, {"points", points_json(axes, res.points)}};
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
      [](const Case& c, const py::dict& params, const std::string& command, long long seeds, py::object out,
         int threads, py::object progress, py::object format, bool resume, bool overwrite) {
        return sweep(c, params, command, seeds,
                     options_of(out, threads, progress, format, std::nullopt, resume, overwrite));
      },
      py::arg("case"), py::arg("params"), py::kw_only(), py::arg("command") = "acoustic", py::arg("seeds") = 1,
      py::arg("out") = py::none(),
      py::arg("threads") = 0, py::arg("progress") = py::none(), py::arg("format") = "csv,netcdf",
      py::arg("resume") = false, py::arg("overwrite") = false,
      R"(Runs `command` for every point of a grid of config values, cases in parallel (as `agglo sweep`).

  case     agglo.Case: the base case (not changed)
  params   dict {dotted key: list of values}, e.g. {"projectile.speed": [0.1, 0.2]}; several keys make a
           grid (last key fastest). A str value is TOML text as on the command line (a bare word is a string).
  command  the command run for each case (default "acoustic"; see command_names())
  seeds    N >= 2: every point runs N seeds (derived from the case's seed and the member index; member 0
           is the case's own seed), the seed being the grid's last axis; out also gets sweep_ensemble.csv
           and sweep_ensemble.nc with each point's mean and standard error (default 1: one run per point)
  out, threads, progress, format, resume, overwrite: as for the command functions (no checkpoint);
  out gets sweep.csv and one folder per case.

Returns an agglo.Result whose summary is {"command": ..., "cases": [{"index", "values": {key: value},
"folder", "summary"}, ...]} in grid order (with seeds, also "points": [{"values": {key: value}, "members",
"folder" (member 0's), "stats": {quantity: {"mean", "stderr", "n"}}}, ...]); its seed is 0 and its arrays
are the table of the cases (results.nc).)");
}

}  // namespace agglo::python
