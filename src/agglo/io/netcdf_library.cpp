#include "agglo/io/netcdf_library.hpp"

#include <dlfcn.h>
#include <fmt/format.h>

#include <stdexcept>
#include <string>

namespace agglo::io {

namespace {

std::string loader_message() {
  const char* m = ::dlerror();
  return m != nullptr ? m : "unknown error";
}

NetcdfLibrary load_netcdf() {
  // RTLD_LOCAL: NetCDF's symbols stay out of the global scope (a Python process may load the netCDF4
  // module's own copy beside it; the soname makes both the same library).
  void* lib = ::dlopen(AGGLO_NETCDF_SONAME, RTLD_NOW | RTLD_LOCAL);
  if (lib == nullptr)
    throw std::runtime_error(fmt::format("cannot load the NetCDF library {}: {} (Debian package libnetcdf19)",
                                         AGGLO_NETCDF_SONAME, loader_message()));
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

}  // namespace

const NetcdfLibrary& netcdf() {
  static const NetcdfLibrary api = load_netcdf();
  return api;
}

}  // namespace agglo::io
