#pragma once
// The keyword arguments every command function takes (out, threads, progress, format, checkpoint,
// resume, overwrite), their validation, the run context they make, and the output folder: the user's
// `out`, or a private temporary folder removed after the run when out is None.
#include <filesystem>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // in every file: the casters of std types must agree (ODR)

#include "agglo/run/command.hpp"
#include "results.hpp"
#include "runner.hpp"

namespace agglo::python {

struct RunOptions {
  pybind11::object out = pybind11::none();       // str / os.PathLike / None
  int threads = 0;
  pybind11::object progress = pybind11::none();
  pybind11::object format = pybind11::str("csv,netcdf");
  std::optional<double> checkpoint;
  bool resume = false;
  bool overwrite = false;
};

// The options from the keyword arguments of a command function.
RunOptions options_of(pybind11::object out, int threads, pybind11::object progress, pybind11::object format,
                      std::optional<double> checkpoint, bool resume, bool overwrite);

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
