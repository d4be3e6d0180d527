#include "agglo/io/netcdf_library.hpp"

#include <dlfcn.h>
#include <fmt/format.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace agglo::io {

namespace {

std::string loader_message() {
  const char* m = ::dlerror();
  return m != nullptr ? m : "unknown error";
}

void* netcdf_handle = nullptr;

NetcdfLibrary load_netcdf() {
  // RTLD_LOCAL: NetCDF's symbols stay out of the global scope (a Python process may load the netCDF4
  // module's own copy beside it; the soname makes both the same library).
  void* lib = ::dlopen(AGGLO_NETCDF_SONAME, RTLD_LAZY | RTLD_LOCAL);
  if (lib == nullptr)
    throw std::runtime_error(fmt::format("cannot load the NetCDF library {}: {} (Debian package libnetcdf19)",
                                         AGGLO_NETCDF_SONAME, loader_message()));
  netcdf_handle = lib;
  NetcdfLibrary api;
#define AGGLO_NETCDF_LOAD(name)                                                                              \
  api.name = reinterpret_cast<decltype(api.name)>(::dlsym(lib, "nc_" #name));                                 \
  if (api.name == nullptr)                                                                                     \
    throw std::runtime_error(fmt::format("the NetCDF library {} lacks nc_{}: {}", AGGLO_NETCDF_SONAME, #name,  \
                                         loader_message()));
  AGGLO_NETCDF_FUNCTIONS(AGGLO_NETCDF_LOAD)
#undef AGGLO_NETCDF_LOAD
  return api;
}

// HDF5 keeps its error-printing switch per thread, and NetCDF-C turns printing off only on the thread
// that initialises it: a file read on any other thread (a job of the ensemble runner, the Python module's
// run thread) printed HDF5-DIAG lines for every attribute NetCDF probes and does not find. Turn it off
// once per thread: H5Eset_auto2(H5E_DEFAULT = 0, no handler, no data), found through NetCDF's own
// dependencies; a NetCDF built without HDF5 has no such symbol and nothing to silence.
void silence_hdf5_errors_on_this_thread() {
  using SetAuto = int (*)(std::int64_t, void*, void*);
  static const auto set_auto = reinterpret_cast<SetAuto>(::dlsym(netcdf_handle, "H5Eset_auto2"));
  if (set_auto != nullptr) set_auto(0, nullptr, nullptr);
}

}  // namespace

const NetcdfLibrary& netcdf() {
  static const NetcdfLibrary api = load_netcdf();
  thread_local const bool silenced = (silence_hdf5_errors_on_this_thread(), true);
  (void)silenced;
  return api;
}

}  // namespace agglo::io
