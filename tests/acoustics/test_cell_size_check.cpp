// The run-time check that the largest collision diameter stays well below the cell (acoustics/run.hpp
// kCellDiameterFraction, docs/acoustics.md §1.8 "Cell size"): fractal aggregates (D_f 1.8) that start below
// the 60 um cell edge (the parse-time check) and grow (coagulation) to collision diameters above 0.1 of it are
// reported in run.log and through the run's warnings; the same aggregates in 6 mm cells (negative control)
// and compact spheres of the same volumes in the 60 um cells are not.
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "agglo/acoustics/run.hpp"
#include "helpers.hpp"

using namespace agglo::acoustics;

namespace {

// 200 soot samples (lognormal around d_v = 0.6 um, 25 nm primaries) in a box of `edge` cells (4 x 1 x 1),
// constant kernel, 5 steps; `structure` the population's structure lines.
std::string cell_box(double edge, const std::string& structure) {
  return fmt::format(R"(
[gas]
gravity = false
[sound]
enabled = false
[domain]
length_x = {}
length_y = {}
length_z = {}
cells_x = 4
min_cells_per_wavelength = 1
{}[output]
efficiency_interval = 1e-4
[[population]]
name = "soot"
phase = "solid"
distribution = "lognormal"
geometric_mean_diameter = 6e-7
geometric_std = 1.5
bins = 10
number_concentration = 1e12
samples = 200
{}
)",
                     4.0 * edge, edge, edge, test::constant_kernel_steps("5e-4"), structure);
}

const std::string kFractal = "structure = \"fractal\"\nprimary_radius = 2.5e-8\nfractal_dimension = 1.8\n"
                             "fractal_prefactor = 1.3\n";

struct Checked {
  AcousticObservations obs;
  std::vector<std::string> warnings;
};
Checked run_checked(const std::string& toml) {
  Checked c;
  RunHooks h;
  h.warning = [&](const std::string& w) { c.warnings.push_back(w); };
  c.obs = run_acoustic(test::parse_case(toml), h);
  return c;
}

bool has_cell_warning(const Checked& c) {
  bool hook = false;
  for (const auto& w : c.warnings) hook = hook || w.rfind("cell size:", 0) == 0;
  const bool log = c.obs.log.find("warning: cell size: the largest collision diameter exceeded 0.1") != std::string::npos;
  EXPECT_EQ(hook, log) << c.obs.log;
  return log;
}

}  // namespace

TEST(CellSizeCheck, LargeCollisionDiametersAreReported) {
  const double edge = 60e-6;
  const Checked small = run_checked(cell_box(edge, kFractal));
  ASSERT_FALSE(small.obs.efficiency.empty());
  double largest = 0.0;
  for (const auto& r : small.obs.efficiency) largest = std::max(largest, r.largest_collision_diameter);
  EXPECT_GT(largest, kCellDiameterFraction * edge);  // the fractal diameters pass the threshold
  EXPECT_LT(small.obs.efficiency.front().largest_collision_diameter, edge);  // the start passed the parse check
  EXPECT_DOUBLE_EQ(small.obs.min_cell_edge, edge);
  EXPECT_TRUE(has_cell_warning(small));
  EXPECT_NE(small.obs.log.find(fmt::format("of {} efficiency rows", small.obs.efficiency.size())), std::string::npos)
      << small.obs.log;
  // negative controls: a hundred times larger cells; compact spheres of the same volumes
  EXPECT_FALSE(has_cell_warning(run_checked(cell_box(100.0 * edge, kFractal))));
  const Checked compact = run_checked(cell_box(edge, ""));
  for (const auto& r : compact.obs.efficiency) EXPECT_LT(r.largest_collision_diameter, kCellDiameterFraction * edge);
  EXPECT_FALSE(has_cell_warning(compact));
}
