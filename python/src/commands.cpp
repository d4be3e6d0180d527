// One Python function per command of the run pipeline (run/commands.hpp): agglo.collide, agglo.vcrit, ...
// Each copies the case, applies its shortcuts (collide: speed), runs run::execute on a worker thread
// (runner.hpp) into `out` or a temporary folder, and returns an agglo.Result.
#include <deque>
#include <limits>

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
const char* doc_of(const run::Command& cmd, const std::string& call, const std::string& shortcuts) {
  return kept(fmt::format("{}({}out=None, threads=0, progress=None, format=\"csv,netcdf\", checkpoint=None, "
                          "resume=False, overwrite=False, max_steps=None, max_memory=None, max_output=None)\n\n"
                          "{}.\n\n  case       agglo.Case (not changed: the run uses a copy)\n{}{}\n\n"
                          "Returns an agglo.Result (summary, seed, out, NumPy arrays).",
                          cmd.name(), call, cmd.help(), shortcuts, kOptionsDoc));
}

// "-v,--speed" -> "speed" (the argument name of a shortcut).
std::string long_flag(const std::string& flags) {
  const auto at = flags.rfind("--");
  if (at == std::string::npos) throw std::logic_error("python: shortcut without a long flag: " + flags);
  return flags.substr(at + 2);
}

// The function of `cmd`: positional (case, and the shortcut's keyword when the command has one), the
// common keywords (options_of) and seeds for a command with a seed key.
py::object call_command(const run::Command& cmd, const py::args& args, const py::kwargs& kwargs) {
  const auto shortcuts = cmd.shortcuts();
  std::vector<std::string> positional{"case"};
  if (!shortcuts.empty()) positional.push_back(long_flag(shortcuts[0].flags));
  Arguments a(fmt::format("agglo.{}", cmd.name()), args, kwargs, positional);
  const Case& c = case_of(a);
  std::vector<std::string> overrides;
  if (!shortcuts.empty())
    if (const auto value = a.real(positional[1]))
      overrides.push_back(fmt::format("{}={}", shortcuts[0].key->dotted(), toml_value(py::float_(*value))));
  const long long seeds = cmd.seed_key() ? a.integer("seeds", 1, 1, kNoLimit) : 1;
  const auto o = options_of(a, true);
  a.finish();
  return py::cast(seeds == 1 ? run_command(cmd, c, o, overrides) : run_seed_ensemble(cmd, c, o, seeds));
}

}  // namespace

void bind_commands(py::module_& m) {
  for (const run::Command* cmd : run::all_commands()) {
    const auto shortcuts = cmd->shortcuts();
    if (shortcuts.size() > 1) throw std::logic_error("python: only one shortcut per command is bound");
    std::string doc, call = "case";
    if (shortcuts.size() == 1) {  // collide's speed: a keyword that sets its config key
      const run::Shortcut sc = shortcuts[0];
      const auto arg = long_flag(sc.flags);
      call += ", " + arg + "=None";
      doc = fmt::format("  {:<10} {} [{}] (sets {}; None: the case's value)\n", arg, sc.key->info().meaning,
                        sc.key->info().unit, sc.key->dotted());
    }
    call += ", *, ";
    if (cmd->seed_key()) {  // acoustic: seeds=N
      call += "seeds=1, ";
      doc += fmt::format("  seeds      N >= 2: a seed ensemble of N members (seeds from {} and the member "
                         "index; docs/acoustics.md): the summary gives every scalar's mean, stderr and n, "
                         "the arrays the mean and stderr of every result; 1: the single run\n",
                         cmd->seed_key()->dotted());
    }
    m.def(
        std::string(cmd->name()).c_str(),
        [cmd](const py::args& args, const py::kwargs& kwargs) { return call_command(*cmd, args, kwargs); },
        doc_of(*cmd, call, doc));
  }
  m.def("command_names", &run::command_names, "The names of the commands, each a function of this module.");
}

}  // namespace agglo::python
