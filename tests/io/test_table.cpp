// io::Table (io/table.hpp): one declaration renders the CSV file and the results.nc variables.
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agglo/io/dataset_scalars.hpp"
#include "agglo/io/table.hpp"

using namespace agglo;

namespace {

// --- The worked example of docs/contributing.md, "Adding an output column" (keep the two equal) ---
struct Sample {
  double t;          // [s]
  double n_per_m3;   // [1/m^3]
  long collisions;
};

io::Table concentration_table(const std::vector<Sample>& rows) {
  io::Table t("concentration.csv", {{"time", rows.size()}}, "{:.8g}");
  t.real("time", "s", "simulated time", io::reals_of(rows, [](const Sample& r) { return r.t; })).header({"t_s"});
  t.real("n_cm3", "cm-3", "number concentration",
         io::reals_of(rows, [](const Sample& r) { return r.n_per_m3 * 1e-6; }));  // displayed per cm^3
  t.integer("collisions", "1", "collisions so far", io::ints_of(rows, [](const Sample& r) { return r.collisions; }));
  return t;
}
// --- end of the worked example ---

std::string csv(const io::Table& t) {
  std::ostringstream os;
  t.write_csv(os);
  return os.str();
}

}  // namespace

// The function above is the one docs/contributing.md shows, character for character.
TEST(Table, WorkedExampleIsTheDocs) {
  auto read = [](const std::string& rel) {
    std::ifstream f(std::string(AGGLO_SOURCE_DIR) + "/" + rel);
    return std::string(std::istreambuf_iterator<char>(f), {});
  };
  const std::string self = read("tests/io/test_table.cpp"), doc = read("docs/contributing.md");
  const auto from = self.find("io::Table concentration_table(");
  ASSERT_NE(from, std::string::npos);
  const std::string function = self.substr(from, self.find("\n}\n", from) + 3 - from);
  EXPECT_NE(doc.find("```cpp\n" + function + "```"), std::string::npos) << function;
}

TEST(Table, WorkedExampleRendersCsvAndDataset) {
  const auto t = concentration_table({{0.0, 2e6, 0}, {0.5, 1.5e6, 3}});
  EXPECT_EQ(csv(t), "t_s,n_cm3,collisions\n0,2,0\n0.5,1.5,3\n");
  io::Dataset d;
  t.add_to(d);
  ASSERT_EQ(d.dims.size(), 1u);
  EXPECT_EQ(d.dim_length("time"), 2u);
  ASSERT_EQ(d.variables.size(), 3u);
  const auto* n = d.find("n_cm3");
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(n->units, "cm-3");
  EXPECT_EQ(n->long_name, "number concentration");
  EXPECT_EQ(n->dims, std::vector<std::string>{"time"});
  ASSERT_EQ(n->reals.size(), 2u);
  EXPECT_DOUBLE_EQ(n->reals[0], 2.0);
  EXPECT_DOUBLE_EQ(n->reals[1], 1.5);
  const auto* c = d.find("collisions");
  ASSERT_NE(c, nullptr);
  EXPECT_TRUE(c->integer);
  EXPECT_EQ(c->ints, (std::vector<std::int64_t>{0, 3}));
  EXPECT_EQ(d.find("t_s"), nullptr);  // the CSV header only; the variable is the coordinate "time"
}

// Two row dimensions: the CSV has one line per (time, bin), a column over one of them repeats along the
// other; results.nc stores each column over its own dimensions, coordinates first.
TEST(Table, GridColumnsRepeatInCsvAndKeepTheirDimsInDataset) {
  io::Table t("grid.csv", {{"t", 2}, {"bin", 3}}, "{:g}");
  t.add_dim("edge", 4);
  t.real("lo", "m", "lower edge", {1, 2, 3}).over({"bin"});
  t.real("t", "s", "time", {10, 20}).over({"t"}).header({"t_s"});
  t.real("edge", "m", "edges", {1, 2, 3, 4}).over({"edge"}).header({});
  t.real("n", "1", "count", {1, 2, 3, 4, 5, 6});
  EXPECT_EQ(csv(t), "lo,t_s,n\n1,10,1\n2,10,2\n3,10,3\n1,20,4\n2,20,5\n3,20,6\n");
  io::Dataset d;
  t.add_to(d);
  std::vector<std::string> names;
  for (const auto& v : d.variables) names.push_back(v.name);
  EXPECT_EQ(names, (std::vector<std::string>{"t", "edge", "lo", "n"}));
  EXPECT_EQ(d.find("n")->dims, (std::vector<std::string>{"t", "bin"}));
  EXPECT_EQ(d.dims.size(), 3u);
}

// A column whose last dimension is not a row spreads over one CSV column per component; a flag column
// writes its words to the CSV and its codes with flag_values / flag_meanings to results.nc.
TEST(Table, ComponentsAndFlags) {
  io::Table t("p.csv", {{"particle", 2}}, "{:g}");
  t.add_dim("xyz", 3);
  t.real("force", "N", "force", {1, 2, 3, 4, 5, 6}).over({"particle", "xyz"}).header({"fx", "fy", "fz"});
  t.flag("phase", "phase", {"solid", "liquid"}, {1, 0});
  t.real("hidden", "1", "results.nc only", {7, 8}).header({});
  EXPECT_EQ(csv(t), "fx,fy,fz,phase\n1,2,3,liquid\n4,5,6,solid\n");
  io::Dataset d;
  t.add_to(d);
  const auto* p = d.find("phase");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->attributes.at("flag_meanings"), "solid liquid");
  EXPECT_EQ(p->attributes.at("flag_values"), nlohmann::json({0, 1}));
  EXPECT_NE(d.find("hidden"), nullptr);
}

TEST(Table, MisfitColumnsAreRefused) {
  io::Table t("bad.csv", {{"row", 2}}, "{:g}");
  t.real("a", "1", "three values for two rows", {1, 2, 3});
  EXPECT_THROW(csv(t), std::logic_error);
  io::Table u("bad.csv", {{"row", 1}}, "{:g}");
  u.add_dim("xyz", 3);
  u.real("v", "1", "two headers for three components", {1, 2, 3}).over({"row", "xyz"}).header({"a", "b"});
  EXPECT_THROW(csv(u), std::logic_error);
}

TEST(Table, UnitsOfSummaryKeysFromTheirSuffix) {
  EXPECT_EQ(io::units_of_key("pm2_5_vol_ug_m3"), "ug m-3");  // a mass concentration, not the volume "m3"
  EXPECT_EQ(io::units_of_key("cell_volume_m3"), "m3");
  EXPECT_EQ(io::units_of_key("n_total_final_cm3"), "cm-3");
  EXPECT_EQ(io::units_of_key("u_amp_m_s"), "m s-1");
  EXPECT_EQ(io::units_of_key("wall_time_s"), "s");
  EXPECT_EQ(io::units_of_key("fine_efficiency"), "1");
}
