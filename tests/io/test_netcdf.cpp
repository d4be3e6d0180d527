// The NetCDF-4 writer (src/agglo/io/netcdf_writer.hpp): a dataset written and read back with the netCDF C
// API keeps its dimensions, values, types, units/long_name and global attributes; a failing write leaves
// no results.nc (nor its temporary file) and an earlier results.nc as it was.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <netcdf.h>
#include <unistd.h>

#include "agglo/io/netcdf_writer.hpp"

using namespace agglo;
using namespace agglo::io;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("agglo_netcdf_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

Dataset sample() {
  Dataset d;
  d.add_dim("time", 3);
  d.add_dim("xyz", 3);
  d.add_dim("fragment", 0);
  d.add("time", {"time"}, "s", "simulated time", {0.0, 0.5, 1.25});
  d.add("kinetic_energy", {"time"}, "J", "kinetic energy", {1e-12, 2e-12, -3.5});
  d.add_ints("n_contacts", {"time"}, "1", "number of contacts", {4, 5, 1LL << 40});
  d.add("position", {"time", "xyz"}, "m", "position", {1, 2, 3, 4, 5, 6, 7, 8, 9})
      .attributes["comment"] = "row-major";
  d.add("energy", {}, "J", "total energy", {2.5});
  d.add("fragment_size", {"fragment"}, "1", "members", {});
  d.attributes["title"] = "a test";
  d.attributes["seed"] = 42;
  d.attributes["ratio"] = 0.25;
  d.attributes["bracket"] = {1.5, 2.5};
  d.attributes["flag"] = true;
  return d;
}

std::string text_att(int nc, int var, const char* name) {
  std::size_t len = 0;
  EXPECT_EQ(nc_inq_attlen(nc, var, name, &len), NC_NOERR) << name;
  std::string s(len, '\0');
  EXPECT_EQ(nc_get_att_text(nc, var, name, s.data()), NC_NOERR) << name;
  return s;
}

int var_id(int nc, const char* name) {
  int id = -1;
  EXPECT_EQ(nc_inq_varid(nc, name, &id), NC_NOERR) << name;
  return id;
}

}  // namespace

TEST(NetcdfWriter, RoundTrip) {
  const auto dir = fresh_dir("roundtrip");
  write_netcdf(OutputDir(dir), sample(), "results.nc", {{"seed", 7}, {"command", "collide"}});
  int nc = -1;
  ASSERT_EQ(nc_open((dir / "results.nc").c_str(), NC_NOWRITE, &nc), NC_NOERR);
  int format = 0;
  ASSERT_EQ(nc_inq_format(nc, &format), NC_NOERR);
  EXPECT_EQ(format, NC_FORMAT_NETCDF4);
  int ndims = 0, nvars = 0;
  ASSERT_EQ(nc_inq(nc, &ndims, &nvars, nullptr, nullptr), NC_NOERR);
  EXPECT_EQ(ndims, 3);
  EXPECT_EQ(nvars, 6);
  int time_dim = -1;
  std::size_t len = 0;
  ASSERT_EQ(nc_inq_dimid(nc, "time", &time_dim), NC_NOERR);
  ASSERT_EQ(nc_inq_dimlen(nc, time_dim, &len), NC_NOERR);
  EXPECT_EQ(len, 3u);

  const int ke = var_id(nc, "kinetic_energy");
  std::vector<double> x(3);
  ASSERT_EQ(nc_get_var_double(nc, ke, x.data()), NC_NOERR);
  EXPECT_EQ(x, (std::vector<double>{1e-12, 2e-12, -3.5}));
  EXPECT_EQ(text_att(nc, ke, "units"), "J");
  EXPECT_EQ(text_att(nc, ke, "long_name"), "kinetic energy");
  nc_type type = 0;
  ASSERT_EQ(nc_inq_vartype(nc, ke, &type), NC_NOERR);
  EXPECT_EQ(type, NC_DOUBLE);

  const int nk = var_id(nc, "n_contacts");
  ASSERT_EQ(nc_inq_vartype(nc, nk, &type), NC_NOERR);
  EXPECT_EQ(type, NC_INT64);
  std::vector<long long> n(3);
  ASSERT_EQ(nc_get_var_longlong(nc, nk, n.data()), NC_NOERR);
  EXPECT_EQ(n, (std::vector<long long>{4, 5, 1LL << 40}));

  const int pos = var_id(nc, "position");
  int vd = 0, dims[2] = {-1, -1};
  ASSERT_EQ(nc_inq_varndims(nc, pos, &vd), NC_NOERR);
  EXPECT_EQ(vd, 2);
  ASSERT_EQ(nc_inq_vardimid(nc, pos, dims), NC_NOERR);
  char dname[NC_MAX_NAME + 1];
  ASSERT_EQ(nc_inq_dimname(nc, dims[1], dname), NC_NOERR);
  EXPECT_STREQ(dname, "xyz");
  std::vector<double> p(9);
  ASSERT_EQ(nc_get_var_double(nc, pos, p.data()), NC_NOERR);
  EXPECT_EQ(p[5], 6.0);
  EXPECT_EQ(text_att(nc, pos, "comment"), "row-major");

  const int e = var_id(nc, "energy");
  ASSERT_EQ(nc_inq_varndims(nc, e, &vd), NC_NOERR);
  EXPECT_EQ(vd, 0);
  double ev = 0;
  ASSERT_EQ(nc_get_var_double(nc, e, &ev), NC_NOERR);
  EXPECT_EQ(ev, 2.5);

  EXPECT_EQ(text_att(nc, NC_GLOBAL, "title"), "a test");
  long long seed = 0;
  ASSERT_EQ(nc_get_att_longlong(nc, NC_GLOBAL, "seed", &seed), NC_NOERR);
  EXPECT_EQ(seed, 7);  // the extra attributes replace the dataset's own
  EXPECT_EQ(text_att(nc, NC_GLOBAL, "command"), "collide");
  double ratio = 0;
  ASSERT_EQ(nc_get_att_double(nc, NC_GLOBAL, "ratio", &ratio), NC_NOERR);
  EXPECT_EQ(ratio, 0.25);
  ASSERT_EQ(nc_inq_attlen(nc, NC_GLOBAL, "bracket", &len), NC_NOERR);
  ASSERT_EQ(len, 2u);
  double br[2];
  ASSERT_EQ(nc_get_att_double(nc, NC_GLOBAL, "bracket", br), NC_NOERR);
  EXPECT_EQ(br[1], 2.5);
  long long flag = 0;
  ASSERT_EQ(nc_get_att_longlong(nc, NC_GLOBAL, "flag", &flag), NC_NOERR);
  EXPECT_EQ(flag, 1);
  EXPECT_EQ(nc_close(nc), NC_NOERR);
  fs::remove_all(dir);
}

TEST(NetcdfWriter, FailedWriteLeavesNoFile) {
  const auto dir = fresh_dir("atomic");
  Dataset bad = sample();
  bad.add("bad/name", {"time"}, "1", "a name netCDF refuses", {1, 2, 3});
  try {
    write_netcdf(OutputDir(dir), bad);
    FAIL() << "expected a failure";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("results.nc"), std::string::npos) << msg;
    EXPECT_NE(msg.find("bad/name"), std::string::npos) << msg;
  }
  EXPECT_TRUE(fs::is_empty(dir));  // neither results.nc nor a temporary file

  write_netcdf(OutputDir(dir), sample());
  const auto size = fs::file_size(dir / "results.nc");
  std::ifstream f(dir / "results.nc", std::ios::binary);
  std::stringstream before;
  before << f.rdbuf();
  EXPECT_THROW(write_netcdf(OutputDir(dir), bad), std::runtime_error);
  std::ifstream g(dir / "results.nc", std::ios::binary);
  std::stringstream after;
  after << g.rdbuf();
  EXPECT_EQ(fs::file_size(dir / "results.nc"), size);
  EXPECT_EQ(before.str(), after.str());  // the earlier file is untouched
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);
  fs::remove_all(dir);
}
