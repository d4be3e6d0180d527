#include "agglo/io/netcdf_writer.hpp"

#include <fmt/format.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "agglo/core/cancel.hpp"
#include "agglo/io/netcdf_library.hpp"

namespace agglo::io {

namespace {

// True when the folder of `file` is read-only or has no free block left.
bool disk_unusable(const std::filesystem::path& file) {
  struct statvfs s {};
  if (::statvfs(file.parent_path().c_str(), &s) != 0) return false;
  return (s.f_flag & ST_RDONLY) != 0 || s.f_bavail == 0;
}

// Throws, naming the file and the operation, unless a netCDF call returned NC_NOERR: OutputError (exit 2)
// for a system error (netCDF's positive codes are errno values) or a full or read-only disk (HDF5
// reports ENOSPC as a generic NC_EHDFERR), else an internal error.
struct Check {
  const std::filesystem::path& file;
  void operator()(int status, const std::string& what) const {
    if (status == NC_NOERR) return;
    if (status > 0) throw output_error(file, status);
    if (disk_unusable(file)) throw output_error(file, ENOSPC);
    throw std::runtime_error(fmt::format("cannot write {}: {}: {}", file.string(), what, netcdf().strerror(status)));
  }
};

// Bytes the file takes at most: 8 per value, the attributes' text, 1 KiB of HDF5 metadata per variable
// and 64 KiB for the file (the collide file of the tetrahedron: 41.6 KB for 27 variables, 31 KB of
// them metadata; estimated 105 KB).
double netcdf_bytes(const Dataset& d, const nlohmann::json& extra) {
  double b = 64.0 * 1024.0 + static_cast<double>(extra.dump().size() + d.attributes.dump().size());
  for (const auto& v : d.variables)
    b += 8.0 * static_cast<double>(v.size()) + 1024.0 + static_cast<double>(v.attributes.dump().size());
  return b;
}

// OutputError before HDF5 touches the disk when the folder is read-only or has less free space than the
// file may need: HDF5 meeting ENOSPC inside a write leaves its file in a state where nc_abort, or its
// own clean-up at exit, crashes (SIGSEGV, issue 23).
void check_space(const std::filesystem::path& file, double bytes) {
  struct statvfs s {};
  if (::statvfs(file.parent_path().c_str(), &s) != 0) return;
  if ((s.f_flag & ST_RDONLY) != 0) throw output_error(file, EROFS);
  const double free = static_cast<double>(s.f_bavail) * static_cast<double>(s.f_frsize);
  if (free < bytes)
    throw output_error(file, fmt::format("No space left on device ({:.0f} KiB free, it needs up to {:.0f} KiB)",
                                         free / 1024.0, bytes / 1024.0));
}

bool all_numbers(const nlohmann::json& a) {
  if (!a.is_array() || a.empty()) return false;
  for (const auto& v : a)
    if (!v.is_number()) return false;
  return true;
}

bool all_integers(const nlohmann::json& a) {
  for (const auto& v : a)
    if (!v.is_number_integer()) return false;
  return true;
}

// One attribute of variable `var` (NC_GLOBAL for the file) from a JSON value.
void put_attribute(const Check& ok, int nc, int var, const std::string& key, const nlohmann::json& v) {
  const std::string what = fmt::format("attribute {}", key);
  if (v.is_string()) {
    const auto& s = v.get_ref<const std::string&>();
    ok(netcdf().put_att_text(nc, var, key.c_str(), s.size(), s.c_str()), what);
  } else if (v.is_boolean() || v.is_number_integer()) {
    const long long x = v.is_boolean() ? (v.get<bool>() ? 1 : 0) : v.get<long long>();
    ok(netcdf().put_att_longlong(nc, var, key.c_str(), NC_INT64, 1, &x), what);
  } else if (v.is_number()) {
    const double x = v.get<double>();
    ok(netcdf().put_att_double(nc, var, key.c_str(), NC_DOUBLE, 1, &x), what);
  } else if (all_numbers(v) && all_integers(v)) {
    const auto x = v.get<std::vector<long long>>();
    ok(netcdf().put_att_longlong(nc, var, key.c_str(), NC_INT64, x.size(), x.data()), what);
  } else if (all_numbers(v)) {
    const auto x = v.get<std::vector<double>>();
    ok(netcdf().put_att_double(nc, var, key.c_str(), NC_DOUBLE, x.size(), x.data()), what);
  } else {
    put_attribute(ok, nc, var, key, nlohmann::json(v.dump()));
  }
}

void put_attributes(const Check& ok, int nc, int var, const nlohmann::json& attrs) {
  for (auto it = attrs.begin(); it != attrs.end(); ++it) put_attribute(ok, nc, var, it.key(), it.value());
}

// Defines the dimensions and variables with their attributes; returns the variable ids.
std::vector<int> define(const Check& ok, int nc, const Dataset& d) {
  std::vector<int> dim_ids;
  for (const auto& [name, len] : d.dims) {
    int id = 0;  // a dimension of length 0 becomes unlimited (NC_UNLIMITED == 0) and stays empty
    ok(netcdf().def_dim(nc, name.c_str(), len, &id), fmt::format("dimension {}", name));
    dim_ids.push_back(id);
  }
  std::vector<int> var_ids;
  for (const auto& v : d.variables) {
    std::vector<int> dims;
    for (const auto& dn : v.dims)
      for (std::size_t k = 0; k < d.dims.size(); ++k)
        if (d.dims[k].first == dn) dims.push_back(dim_ids[k]);
    int id = 0;
    ok(netcdf().def_var(nc, v.name.c_str(), v.integer ? NC_INT64 : NC_DOUBLE, static_cast<int>(dims.size()), dims.data(),
                  &id),
       fmt::format("variable {}", v.name));
    put_attribute(ok, nc, id, "units", v.units);
    put_attribute(ok, nc, id, "long_name", v.long_name);
    put_attributes(ok, nc, id, v.attributes);
    var_ids.push_back(id);
  }
  put_attributes(ok, nc, NC_GLOBAL, d.attributes);
  return var_ids;
}

void write_values(const Check& ok, int nc, const Dataset& d, const std::vector<int>& ids) {
  for (std::size_t k = 0; k < d.variables.size(); ++k) {
    const auto& v = d.variables[k];
    if (v.size() == 0) continue;
    poll_cancel();  // a long write stops between variables (core/cancel.hpp)
    const std::string what = fmt::format("values of {}", v.name);
    if (v.integer) {
      std::vector<long long> x(v.ints.begin(), v.ints.end());
      ok(netcdf().put_var_longlong(nc, ids[k], x.data()), what);
    } else {
      ok(netcdf().put_var_double(nc, ids[k], v.reals.data()), what);
    }
  }
}

}  // namespace

std::mutex& netcdf_library_mutex() {
  static std::mutex m;
  return m;
}

void write_netcdf(const OutputDir& out, const Dataset& d, const std::string& name,
                  const nlohmann::json& extra_attributes) {
  const auto path = out.file(name);
  auto tmp = path;
  tmp += fmt::format(".tmp-{}", static_cast<long>(::getpid()));
  const Check ok{path};
  check_space(path, netcdf_bytes(d, extra_attributes));
  int nc = -1;
  const WriteCancelScope live;  // results flushed after an interruption are written whole
  const std::lock_guard lock(netcdf_library_mutex());
  try {
    ok(netcdf().create(tmp.c_str(), NC_NETCDF4 | NC_CLOBBER, &nc), "create");
    const auto ids = define(ok, nc, d);
    put_attributes(ok, nc, NC_GLOBAL, extra_attributes);
    ok(netcdf().enddef(nc), "end of definitions");
    write_values(ok, nc, d, ids);
    const int status = netcdf().close(nc);
    nc = -1;
    ok(status, "close");
  } catch (const OutputError&) {
    // The disk failed under HDF5 after check_space (another writer filled it): no nc_abort, which crashes
    // there; the handle stays open (HDF5 may still crash when it closes it at exit: not avoidable here).
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  } catch (...) {
    if (nc >= 0) netcdf().abort(nc);
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    const int err = ec.value();
    std::filesystem::remove(tmp, ec);
    throw output_error(path, err);
  }
}

}  // namespace agglo::io
