// RunOptions, RunFolder (options.hpp).
#include "options.hpp"

#include <cstdlib>
#include <system_error>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "agglo/core/error.hpp"

namespace py = pybind11;

namespace agglo::python {

namespace {

// The value as the user wrote it, cut to 40 characters.
std::string shown(const py::handle& v) {
  std::string s = py::repr(v).cast<std::string>();
  return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}

// "csv", "netcdf", "csv,netcdf" or a list of those names, read by run::parse_formats (as the CLI's --format).
run::OutputFormats formats_of(const py::object& format) {
  if (py::isinstance<py::str>(format)) return run::parse_formats(format.cast<std::string>());
  std::string text;
  for (auto n : format) {
    if (!py::isinstance<py::str>(n))
      throw ConfigError(fmt::format("format: {} is not a format name (csv, netcdf)", shown(n)));
    if (!text.empty()) text += ',';
    text += n.cast<std::string>();
  }
  return run::parse_formats(text);
}

}  // namespace

Arguments::Arguments(std::string fn, const py::args& args, const py::kwargs& kwargs, std::vector<std::string> positional)
    : fn_(std::move(fn)), args_(args), kwargs_(kwargs.attr("copy")()), positional_(std::move(positional)) {}

py::object Arguments::take(const std::string& name) {
  for (std::size_t k = 0; k < positional_.size(); ++k) {
    if (positional_[k] != name || k >= args_.size()) continue;
    if (kwargs_.contains(name)) throw ConfigError(fmt::format("{}: {} given twice (by position and keyword)", fn_, name));
    return args_[k];
  }
  if (!kwargs_.contains(name)) return py::none();
  py::object v = kwargs_[py::str(name)];
  PyDict_DelItemString(kwargs_.ptr(), name.c_str());
  return v;
}

void Arguments::fail(const std::string& name, const py::handle& value, const std::string& allowed) const {
  throw ConfigError(fmt::format("{}: {} = {}: {}", fn_, name, shown(value), allowed));
}

long long Arguments::integer(const std::string& name, long long fallback, long long lo, long long hi) {
  const py::object v = take(name);
  if (v.is_none()) return fallback;
  const auto allowed = hi == kNoLimit ? fmt::format("give an integer >= {}", lo)
                                      : fmt::format("give an integer from {} to {}", lo, hi);
  if (py::isinstance<py::bool_>(v) || !py::hasattr(v, "__index__")) fail(name, v, allowed);
  PyObject* index = PyNumber_Index(v.ptr());
  if (!index) {
    PyErr_Clear();
    fail(name, v, allowed);
  }
  int overflow = 0;
  const long long n = PyLong_AsLongLongAndOverflow(index, &overflow);
  Py_DECREF(index);
  if (overflow != 0 || n < lo || n > hi) fail(name, v, allowed);
  return n;
}

std::optional<double> Arguments::real(const std::string& name) {
  const py::object v = take(name);
  if (v.is_none()) return std::nullopt;
  const double x = PyFloat_AsDouble(v.ptr());
  if (py::isinstance<py::bool_>(v) || py::isinstance<py::str>(v) || (x == -1.0 && PyErr_Occurred())) {
    PyErr_Clear();
    fail(name, v, "give a real number");
  }
  return x;
}

bool Arguments::flag(const std::string& name, bool fallback) {
  const py::object v = take(name);
  if (v.is_none()) return fallback;
  if (!py::isinstance<py::bool_>(v) && !py::isinstance(v, py::module_::import("numpy").attr("bool_")))
    fail(name, v, "give True or False");
  return v.cast<bool>();
}

std::optional<std::string> Arguments::text(const std::string& name) {
  const py::object v = take(name);
  if (v.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::isinstance<py::bool_>(v) || !(py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)))
    fail(name, v, "give a number or a str");
  return py::str(v).cast<std::string>();
}

void Arguments::finish() const {
  if (args_.size() > positional_.size())
    throw ConfigError(fmt::format("{}: {} positional argument(s) given, at most {} ({}); the others are keywords",
                                  fn_, args_.size(), positional_.size(), fmt::join(positional_, ", ")));
  for (auto [k, v] : kwargs_)
    throw ConfigError(fmt::format("{}: unknown keyword argument '{}' (help({}) lists them)", fn_,
                                  py::str(k).cast<std::string>(), fn_));
}

const Case& case_of(Arguments& a) {
  const py::object c = a.take("case");
  if (c.is_none()) throw ConfigError(fmt::format("{}: case missing: give an agglo.Case", a.function()));
  if (!py::isinstance<Case>(c)) a.fail("case", c, "give an agglo.Case");
  return c.cast<const Case&>();
}

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
  max_steps, max_memory, max_output
             the run budgets (docs/limits.md): particle-steps (e.g. 2e12), bytes or a size text ("8G", "512M");
             None (default): the environment's AGGLO_MAX_STEPS, AGGLO_MAX_MEMORY, AGGLO_MAX_OUTPUT, else the defaults
  resume     continue the run in out (ensembles: reuse the finished jobs of its journal; restartable runs:
             continue from the last checkpoint)
  overwrite  replace an earlier agglo run in out
The GIL is released while the run goes on; Ctrl-C cancels it and raises agglo.InterruptedError.
A wrong or unknown argument raises ConfigError naming it (one line).
Raises ConfigError (bad case or option), LimitError (beyond a run budget), NumericalError, InterruptedError.)";

RunOptions options_of(Arguments& a, bool with_checkpoint) {
  RunOptions o;
  o.out = a.take("out");
  if (!o.out.is_none() && !py::isinstance<py::str>(o.out) && !py::hasattr(o.out, "__fspath__"))
    a.fail("out", o.out, "give a folder (str or os.PathLike) or None");
  o.threads = static_cast<int>(a.integer("threads", 0, 0, kMaxThreads));
  o.progress = a.take("progress");
  if (!o.progress.is_none() && !PyCallable_Check(o.progress.ptr()))
    a.fail("progress", o.progress, "give a callable progress(fraction, sim_time) or None");
  o.format = a.take("format");
  if (o.format.is_none()) o.format = py::str("csv,netcdf");
  else if (!py::isinstance<py::str>(o.format) && !py::isinstance<py::list>(o.format) &&
           !py::isinstance<py::tuple>(o.format))
    a.fail("format", o.format, "give \"csv\", \"netcdf\", \"csv,netcdf\" or a list of those");
  if (with_checkpoint) o.checkpoint = a.real("checkpoint");
  o.resume = a.flag("resume", false);
  o.overwrite = a.flag("overwrite", false);
  o.budgets = run::resolve_budgets({});
  if (const auto s = a.text("max_steps")) o.budgets.max_steps = run::parse_steps(*s, "max_steps");
  if (const auto s = a.text("max_memory")) o.budgets.max_memory_bytes = run::parse_size(*s, "max_memory");
  if (const auto s = a.text("max_output")) o.budgets.max_output_bytes = run::parse_size(*s, "max_output");
  return o;
}

run::RunContext context_of(const run::Command& cmd, const RunOptions& o) {
  if (o.threads < 0) throw ConfigError(fmt::format("threads = {}: give 0 (all cores) or more", o.threads));
  if (o.resume && o.overwrite) throw ConfigError("resume and overwrite exclude each other");
  run::RunContext ctx;
  ctx.threads = o.threads;
  ctx.resume = o.resume;
  ctx.overwrite = o.overwrite;
  ctx.budgets = &o.budgets;
  const run::OutputFormats formats = formats_of(o.format);  // checked with or without out (issue 23 item 12)
  ctx.formats = o.out.is_none() ? run::OutputFormats{false, false} : formats;
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
