// One Python function per command of the run pipeline (run/commands.hpp): agglo.collide, agglo.vcrit, ...
// Each copies the case, applies its shortcuts (collide: speed), runs run::execute on a worker thread
// (runner.hpp) into `out` or a temporary folder, and returns an agglo.Result.
#include <deque>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "agglo/core/error.hpp"
#include "agglo/core/settings.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/run/ensemble_request.hpp"
#include "bindings.hpp"
#include "case.hpp"
#include "options.hpp"

namespace py = pybind11;

namespace agglo::python {

namespace {

Result run_command(const run::Command& cmd, const Case& c, const RunOptions& o,
                   const std::vector<std::string>& overrides) {
  Config cfg = copy_of(c);
  for (const auto& s : overrides) cfg.apply_override(s);
  const auto ctx = context_of(cmd, o);
  RunFolder folder(o.out);
  auto r = run_released([&](const run::RunContext& x) { return run::execute(cmd, cfg, folder.path(), x); }, ctx,
                        o.progress);
  return Result{std::string(cmd.name()), std::move(r.result.summary), r.result.seed, folder.user_path(),
                std::move(r.result.data), std::move(r.messages)};
}

// seeds = N >= 2: a seed ensemble (a seeded sweep with no axes, run/ensemble_request.hpp, as `agglo acoustic
// --seeds N`); the result's summary holds the members' seeds and folders and every summary scalar's mean,
// stderr and n; its arrays are the ensemble's results.nc.
Result run_seed_ensemble(const run::Command& cmd, const Case& c, const RunOptions& o, long long n) {
  const auto ctx = context_of(cmd, o);
  RunFolder folder(o.out);
  auto plan = run::plan_ensemble({std::string(cmd.name()), copy_of(c), {}, n, folder.path()}, ctx);
  auto r = run_released(
      [&](const run::RunContext& x) {
        const auto ens = run::execute_ensemble(plan, x);
        nlohmann::json stats = nlohmann::json::object(), folders = nlohmann::json::array();
        for (const auto& s : ens.points.at(0).stats)
          stats[s.quantity] = {{"mean", s.value.mean}, {"stderr", s.value.standard_error}, {"n", s.value.n}};
        for (const auto& m : ens.runs.cases) folders.push_back(m.folder);
        run::CommandResult out;
        out.summary = {{"members", plan.seeds.size()}, {"seeds", plan.seeds}, {"folders", folders}, {"ensemble", stats}};
        out.seed = plan.seed;
        out.data = ens.data;
        return out;
      },
      ctx, o.progress);
  return Result{std::string(cmd.name()), std::move(r.result.summary), r.result.seed, folder.user_path(),
                std::move(r.result.data), std::move(r.messages)};
}

// `text` kept alive for the module's lifetime (docstrings, argument names).
const char* kept(std::string text) {
  static std::deque<std::string> texts;
  return texts.emplace_back(std::move(text)).c_str();
}

// The docstring of a command's function.
const char* doc_of(const run::Command& cmd, const std::string& shortcuts) {
  return kept(fmt::format("{}.\n\n  case       agglo.Case (not changed: the run uses a copy)\n{}{}\n\n"
                          "Returns an agglo.Result (summary, seed, out, NumPy arrays).",
                          cmd.help(), shortcuts, kOptionsDoc));
}

// "-v,--speed" -> "speed" (the argument name of a shortcut).
std::string long_flag(const std::string& flags) {
  const auto at = flags.rfind("--");
  if (at == std::string::npos) throw std::logic_error("python: shortcut without a long flag: " + flags);
  return flags.substr(at + 2);
}

}  // namespace

void bind_commands(py::module_& m) {
  for (const run::Command* cmd : run::all_commands()) {
    const std::string name(cmd->name());
    const auto shortcuts = cmd->shortcuts();
    if (shortcuts.size() > 1) throw std::logic_error("python: only one shortcut per command is bound");
    if (shortcuts.size() == 1) {  // collide's speed: a keyword that sets its config key
      const run::Shortcut sc = shortcuts[0];
      const char* arg = kept(long_flag(sc.flags));
      const auto doc = fmt::format("  {:<10} {} [{}] (sets {}; None: the case's value)\n", arg, sc.key->info().meaning,
                                   sc.key->info().unit, sc.key->dotted());
      m.def(
          name.c_str(),
          [cmd, sc](const Case& c, std::optional<double> value, py::object out, int threads,
                             py::object progress, py::object format, std::optional<double> checkpoint, bool resume,
                             bool overwrite) {
            std::vector<std::string> overrides;
            if (value) overrides.push_back(fmt::format("{}={}", sc.key->dotted(), toml_value(py::float_(*value))));
            return run_command(*cmd, c, options_of(out, threads, progress, format, checkpoint, resume, overwrite),
                               overrides);
          },
          py::arg("case"), py::arg_v(arg, py::none(), "None"), py::kw_only(), py::arg("out") = py::none(),
          py::arg("threads") = 0, py::arg("progress") = py::none(), py::arg("format") = "csv,netcdf",
          py::arg("checkpoint") = py::none(), py::arg("resume") = false, py::arg("overwrite") = false,
          doc_of(*cmd, doc));
      continue;
    }
    if (cmd->seed_key()) {  // acoustic: seeds=N
      const auto doc = fmt::format("  seeds      N >= 2: a seed ensemble of N members (seeds from {} and the member "
                                   "index; docs/acoustics.md): the summary gives every scalar's mean, stderr and n, "
                                   "the arrays the mean and stderr of every result; 1: the single run\n",
                                   cmd->seed_key()->dotted());
      m.def(
          name.c_str(),
          [cmd](const Case& c, long long seeds, py::object out, int threads, py::object progress, py::object format,
                std::optional<double> checkpoint, bool resume, bool overwrite) {
            const auto o = options_of(out, threads, progress, format, checkpoint, resume, overwrite);
            return seeds == 1 ? run_command(*cmd, c, o, {}) : run_seed_ensemble(*cmd, c, o, seeds);
          },
          py::arg("case"), py::kw_only(), py::arg("seeds") = 1, py::arg("out") = py::none(), py::arg("threads") = 0,
          py::arg("progress") = py::none(), py::arg("format") = "csv,netcdf", py::arg("checkpoint") = py::none(),
          py::arg("resume") = false, py::arg("overwrite") = false, doc_of(*cmd, doc));
      continue;
    }
    m.def(
        name.c_str(),
        [cmd](const Case& c, py::object out, int threads, py::object progress, py::object format,
                       std::optional<double> checkpoint, bool resume, bool overwrite) {
          return run_command(*cmd, c, options_of(out, threads, progress, format, checkpoint, resume, overwrite), {});
        },
        py::arg("case"), py::kw_only(), py::arg("out") = py::none(), py::arg("threads") = 0,
        py::arg("progress") = py::none(), py::arg("format") = "csv,netcdf", py::arg("checkpoint") = py::none(),
        py::arg("resume") = false, py::arg("overwrite") = false,
        doc_of(*cmd, ""));
  }
  m.def("command_names", &run::command_names, "The names of the commands, each a function of this module.");
}

}  // namespace agglo::python
