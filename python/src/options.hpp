#pragma once
// The keyword arguments every command function takes (out, threads, progress, format, checkpoint,
// resume, overwrite, max_steps, max_memory, max_output), their validation, the run context they make, and the output folder: the user's
// `out`, or a private temporary folder removed after the run when out is None.
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // in every file: the casters of std types must agree (ODR)

#include "agglo/run/command.hpp"
#include "case.hpp"
#include "results.hpp"
#include "runner.hpp"

namespace agglo::python {

// The arguments of a call of a module function (`fn`, e.g. "agglo.collide"): positional ones by name in
// order, then keywords, each read at most once and converted with a one-line ConfigError naming the
// function, the argument, its value and what is allowed (never pybind11's multi-line TypeError);
// finish() refuses keywords nobody read and surplus positional arguments.
class Arguments {
 public:
  Arguments(std::string fn, const pybind11::args& args, const pybind11::kwargs& kwargs,
            std::vector<std::string> positional);
  const std::string& function() const { return fn_; }
  pybind11::object take(const std::string& name);  // None when not given
  long long integer(const std::string& name, long long fallback, long long lo, long long hi);
  std::optional<double> real(const std::string& name);  // nullopt when None or not given
  bool flag(const std::string& name, bool fallback);
  std::optional<std::string> text(const std::string& name);  // str, or a number as its TOML text; nullopt: None
  [[noreturn]] void fail(const std::string& name, const pybind11::handle& value, const std::string& allowed) const;
  void finish() const;

 private:
  std::string fn_;
  pybind11::args args_;
  pybind11::dict kwargs_;
  std::vector<std::string> positional_;
};

struct RunOptions {
  pybind11::object out = pybind11::none();       // str / os.PathLike / None
  int threads = 0;
  pybind11::object progress = pybind11::none();
  pybind11::object format = pybind11::str("csv,netcdf");
  std::optional<double> checkpoint;
  bool resume = false;
  bool overwrite = false;
  run::Budgets budgets;  // the environment's or defaults, replaced by max_steps, max_memory, max_output
};

// `hi` of Arguments::integer for no upper bound.
inline constexpr long long kNoLimit = std::numeric_limits<long long>::max();
// Largest `threads` accepted (docs/limits.md).
inline constexpr long long kMaxThreads = 4096;

// The common keyword arguments of a command function (with checkpoint: commands, not sweep).
RunOptions options_of(Arguments& a, bool with_checkpoint);

// The agglo.Case argument `case` (one-line ConfigError when missing or not a Case).
const Case& case_of(Arguments& a);

// The run context of the options for `cmd` (ConfigError on a bad option, as the CLI's).
run::RunContext context_of(const run::Command& cmd, const RunOptions& o);

// The folder a run writes into: `out`, or a fresh temporary folder (removed by the destructor).
class RunFolder {
 public:
  explicit RunFolder(const pybind11::object& out);
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::optional<std::string> user_path() const;  // none for a temporary folder

 private:
  std::filesystem::path path_, temp_;
};

// The docstring paragraph of the common keyword arguments.
extern const char* const kOptionsDoc;

}  // namespace agglo::python
