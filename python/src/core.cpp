// Cases, errors, commands and results: the parts of the module that drive the run pipeline.
#include "agglo/io/netcdf_library.hpp"

#include "agglo/core/version.hpp"
#include "bindings.hpp"

namespace agglo::python {

void bind_core(pybind11::module_& m) {
  // NetCDF-C silences HDF5's error printing only on the thread that initialises it: do it here, on the
  // importing thread, not on a run's worker thread (else xarray reads print HDF5-DIAG lines).
  io::netcdf().initialize();
  m.attr("__version__") = kVersion;
  m.attr("git_hash") = kGitHash;
  bind_errors(m);
  bind_case(m);
  bind_results(m);
  bind_commands(m);
  bind_sweep(m);
}

}  // namespace agglo::python
