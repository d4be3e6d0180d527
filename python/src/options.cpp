// RunOptions, RunFolder (options.hpp).
#include "options.hpp"

#include <cstdlib>
#include <system_error>

#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace py = pybind11;

namespace agglo::python {

namespace {

// "csv", "netcdf", "csv,netcdf" or a list of those names, read by run::parse_formats (as the CLI's --format).
run::OutputFormats formats_of(const py::object& format) {
  if (py::isinstance<py::str>(format)) return run::parse_formats(format.cast<std::string>());
  std::string text;
  for (const auto& n : format.cast<std::vector<std::string>>()) text += (text.empty() ? "" : ",") + n;
  return run::parse_formats(text);
}

}  // namespace

const char* const kOptionsDoc = R"(
Keyword arguments (all commands):
  out        output folder (str or os.PathLike) written like the CLI's --out; None (default): the run writes
             nothing the user keeps (a private temporary folder, removed afterwards)
  threads    OpenMP threads of this run (default 0: all cores)
  progress   callable progress(fraction, sim_time) with fraction done in [0, 1] and the simulated time [s]
             (0 when not meaningful); called on the calling thread between waits, never from worker threads.
             An exception it raises cancels the run and propagates.
  format     result files in out: "csv", "netcdf" or "csv,netcdf" (default), or a list of those
  checkpoint simulated seconds between checkpoints in out (commands that write checkpoints only; None: none)
  resume     continue the run in out (ensembles: reuse the finished jobs of its journal; restartable runs:
             continue from the last checkpoint)
  overwrite  replace an earlier agglo run in out
The GIL is released while the run goes on; Ctrl-C cancels it and raises agglo.InterruptedError.
Raises ConfigError (bad case or option), LimitError (beyond a run budget), NumericalError, InterruptedError.)";

RunOptions options_of(py::object out, int threads, py::object progress, py::object format,
                      std::optional<double> checkpoint, bool resume, bool overwrite) {
  RunOptions o;
  o.out = std::move(out);
  o.threads = threads;
  o.progress = std::move(progress);
  o.format = std::move(format);
  o.checkpoint = checkpoint;
  o.resume = resume;
  o.overwrite = overwrite;
  return o;
}

run::RunContext context_of(const run::Command& cmd, const RunOptions& o) {
  if (o.threads < 0) throw ConfigError(fmt::format("threads = {}: give 0 (all cores) or more", o.threads));
  if (o.resume && o.overwrite) throw ConfigError("resume and overwrite exclude each other");
  run::RunContext ctx;
  ctx.threads = o.threads;
  ctx.resume = o.resume;
  ctx.overwrite = o.overwrite;
  ctx.formats = o.out.is_none() ? run::OutputFormats{false, false} : formats_of(o.format);
  if (o.checkpoint) {
    if (!cmd.restartable())
      throw ConfigError(fmt::format("{}: checkpoint= is only for commands that write checkpoints", cmd.name()));
    if (!(*o.checkpoint > 0.0))
      throw ConfigError(fmt::format("checkpoint = {}: give a positive interval of simulated seconds", *o.checkpoint));
    ctx.checkpoint_interval = *o.checkpoint;
  }
  if (o.out.is_none() && (o.resume || o.checkpoint))
    throw ConfigError("resume and checkpoint need an output folder (out=)");
  return ctx;
}

RunFolder::RunFolder(const py::object& out) {
  if (!out.is_none()) {
    path_ = py::str(py::module_::import("os").attr("fspath")(out)).cast<std::string>();
    return;
  }
  std::string pattern = (std::filesystem::temp_directory_path() / "agglo-py-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary folder in " + pattern);
  temp_ = pattern;
  path_ = temp_ / "run";
}

RunFolder::~RunFolder() {
  std::error_code ec;
  if (!temp_.empty()) std::filesystem::remove_all(temp_, ec);
}

std::optional<std::string> RunFolder::user_path() const {
  if (!temp_.empty()) return std::nullopt;
  return path_.string();
}

}  // namespace agglo::python
