#include "agglo/io/netcdf_reader.hpp"

#include <fmt/format.h>

#include <string>
#include <vector>

#include "agglo/io/netcdf_library.hpp"
#include "agglo/io/netcdf_writer.hpp"

namespace agglo::io {

namespace {

struct ReadCheck {
  const std::filesystem::path& file;
  void operator()(int status, const std::string& what) const {
    if (status != NC_NOERR)
      throw NetcdfReadError(fmt::format("cannot read {}: {}: {}", file.string(), what, netcdf().strerror(status)));
  }
};

bool integer_type(nc_type t) {
  return t == NC_BYTE || t == NC_SHORT || t == NC_INT || t == NC_INT64 || t == NC_UBYTE || t == NC_USHORT ||
         t == NC_UINT || t == NC_UINT64;
}

// Attribute `name` of variable `var` (NC_GLOBAL for the file) as JSON: text as a string, numbers as a
// number or an array; null for other types.
nlohmann::json read_attribute(const ReadCheck& ok, int nc, int var, const char* name) {
  nc_type type = 0;
  std::size_t len = 0;
  ok(netcdf().inq_att(nc, var, name, &type, &len), fmt::format("attribute {}", name));
  if (type == NC_CHAR) {
    std::string s(len, '\0');
    if (len > 0) ok(netcdf().get_att_text(nc, var, name, s.data()), fmt::format("attribute {}", name));
    return s;
  }
  if (type == NC_STRING || len == 0) return nullptr;
  nlohmann::json out = nlohmann::json::array();
  if (integer_type(type)) {
    std::vector<long long> x(len);
    ok(netcdf().get_att_longlong(nc, var, name, x.data()), fmt::format("attribute {}", name));
    for (long long v : x) out.push_back(v);
  } else {
    std::vector<double> x(len);
    ok(netcdf().get_att_double(nc, var, name, x.data()), fmt::format("attribute {}", name));
    for (double v : x) out.push_back(v);
  }
  return len == 1 ? out[0] : out;
}

nlohmann::json read_attributes(const ReadCheck& ok, int nc, int var, int count) {
  nlohmann::json attrs = nlohmann::json::object();
  for (int a = 0; a < count; ++a) {
    char name[NC_MAX_NAME + 1] = {};
    ok(netcdf().inq_attname(nc, var, a, name), "attribute name");
    nlohmann::json v = read_attribute(ok, nc, var, name);
    if (!v.is_null()) attrs[name] = std::move(v);
  }
  return attrs;
}

void read_variable(const ReadCheck& ok, int nc, int id, Dataset& d) {
  char name[NC_MAX_NAME + 1] = {};
  nc_type type = 0;
  int ndims = 0, natts = 0;
  int dim_ids[NC_MAX_VAR_DIMS] = {};
  ok(netcdf().inq_var(nc, id, name, &type, &ndims, dim_ids, &natts), "variable");
  if (type == NC_CHAR || type == NC_STRING || type > NC_STRING) return;  // text and user types: not numeric
  Variable v;
  v.name = name;
  v.integer = integer_type(type);
  std::size_t n = 1;
  for (int k = 0; k < ndims; ++k) {
    char dn[NC_MAX_NAME + 1] = {};
    std::size_t len = 0;
    ok(netcdf().inq_dim(nc, dim_ids[k], dn, &len), fmt::format("dimension of {}", v.name));
    v.dims.emplace_back(dn);
    n *= len;
  }
  nlohmann::json attrs = read_attributes(ok, nc, id, natts);
  if (attrs.contains("units") && attrs["units"].is_string()) v.units = attrs["units"].get<std::string>();
  if (attrs.contains("long_name") && attrs["long_name"].is_string())
    v.long_name = attrs["long_name"].get<std::string>();
  attrs.erase("units");
  attrs.erase("long_name");
  v.attributes = std::move(attrs);
  const std::string what = fmt::format("values of {}", v.name);
  if (v.integer) {
    std::vector<long long> x(n);
    if (n > 0) ok(netcdf().get_var_longlong(nc, id, x.data()), what);
    v.ints.assign(x.begin(), x.end());
  } else {
    v.reals.resize(n);
    if (n > 0) ok(netcdf().get_var_double(nc, id, v.reals.data()), what);
  }
  d.variables.push_back(std::move(v));
}

Dataset read_open(const ReadCheck& ok, int nc) {
  Dataset d;
  int ndims = 0, nvars = 0, natts = 0, unlimited = 0;
  ok(netcdf().inq(nc, &ndims, &nvars, &natts, &unlimited), "header");
  for (int k = 0; k < ndims; ++k) {
    char name[NC_MAX_NAME + 1] = {};
    std::size_t len = 0;
    ok(netcdf().inq_dim(nc, k, name, &len), "dimension");
    d.dims.emplace_back(name, len);
  }
  for (int k = 0; k < nvars; ++k) read_variable(ok, nc, k, d);
  d.attributes = read_attributes(ok, nc, NC_GLOBAL, natts);
  return d;
}

}  // namespace

Dataset read_netcdf(const std::filesystem::path& file) {
  const ReadCheck ok{file};
  const std::lock_guard lock(netcdf_library_mutex());
  int nc = -1;
  ok(netcdf().open(file.c_str(), NC_NOWRITE, &nc), "open");
  try {
    Dataset d = read_open(ok, nc);
    netcdf().close(nc);
    return d;
  } catch (...) {
    netcdf().close(nc);
    throw;
  }
}

}  // namespace agglo::io
