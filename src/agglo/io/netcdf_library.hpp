#pragma once
// NetCDF-C, loaded when a process first reads or writes a NetCDF file (dlopen of the shared library
// CMake found, by its soname) instead of at process start. Linked directly, NetCDF and the ~45 shared
// libraries it depends on (HDF5, curl, TLS, ...) cost every agglo process about 30 M instructions of
// dynamic-loader symbol lookup before main (callgrind of `agglo --version`; docs/timings.md), also the
// processes that never touch results.nc: errors, dry runs, listings, every GoogleTest process
// (issue 27 item 2). The functions agglo calls are listed once below; each member has the type of the
// NetCDF-C function of the same name with the `nc_` prefix (netcdf.h), so a call reads
// `netcdf().put_var_double(...)` for `nc_put_var_double(...)`.
#include <netcdf.h>

namespace agglo::io {

#define AGGLO_NETCDF_FUNCTIONS(X)                                                                               \
  X(initialize) X(strerror) X(create) X(open) X(close) X(abort) X(enddef) X(def_dim) X(def_var)                 \
  X(put_att_text) X(put_att_longlong) X(put_att_double) X(put_var_longlong) X(put_var_double) X(inq)            \
  X(inq_format) X(inq_dim) X(inq_dimname) X(inq_dimlen) X(inq_dimid) X(inq_var) X(inq_varid) X(inq_vartype)     \
  X(inq_varndims) X(inq_vardimid) X(inq_att) X(inq_attname) X(inq_attlen) X(get_att_text) X(get_att_longlong)   \
  X(get_att_double) X(get_var_double) X(get_var_longlong)

struct NetcdfLibrary {
#define AGGLO_NETCDF_MEMBER(name) decltype(&::nc_##name) name = nullptr;
  AGGLO_NETCDF_FUNCTIONS(AGGLO_NETCDF_MEMBER)
#undef AGGLO_NETCDF_MEMBER
};

// The library's functions, loaded on the first call (thread-safe); throws std::runtime_error naming the
// library and the loader's message when it or one of the functions cannot be loaded. The first call on
// each thread also turns off HDF5's error printing for that thread (NetCDF-C does it only on the thread
// that initialises it), so that reads on worker threads print no HDF5-DIAG lines.
const NetcdfLibrary& netcdf();

}  // namespace agglo::io
