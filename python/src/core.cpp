// Cases, errors, commands and results: the parts of the module that drive the run pipeline.
#include "agglo/core/version.hpp"
#include "bindings.hpp"

namespace agglo::python {

void bind_core(pybind11::module_& m) {
  m.attr("__version__") = kVersion;
  m.attr("git_hash") = kGitHash;
  bind_errors(m);
  bind_case(m);
  bind_results(m);
  bind_commands(m);
  bind_sweep(m);
}

}  // namespace agglo::python
