#pragma once
// Shared helpers of the outcome-table tests (test_outcome_table.cpp, test_breakage.cpp,
// test_fragment_distribution.cpp): table files in
// temporary folders, the constant-kernel box and seed statistics.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <unistd.h>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/io/netcdf_writer.hpp"
#include "helpers.hpp"

namespace agglo::acoustics::test {

// Two solid samples (1 and 2 um, densities 2500 and 1800 kg/m^3) with weights wi, wj and different
// velocities: the pair the breakage tests break (test_breakage.cpp, test_fragment_distribution.cpp).
inline SampleSet pair_of_samples(double wi, double wj, const Gas& gas, const Sound& sound) {
  SampleSet p;
  const double vi = 1e-18 * 0.5235987755982988, vj = 8.0 * vi;
  p.add(0, 0, 0, vi, 0.0, 2500.0 * vi, wi, 0, gas, sound);
  p.add(0, 0, 0, vj, 0.0, 1800.0 * vj, wj, 1, gas, sound);
  p.vx = {0.3, -0.1};
  p.vy = {-0.2, 0.05};
  p.vz = {0.01, 0.7};
  return p;
}

// The folders the tests write their tables into, removed when the test program ends.
struct TableFolders {
  std::vector<std::filesystem::path> made;
  ~TableFolders() {
    std::error_code ec;
    for (const auto& d : made) std::filesystem::remove_all(d, ec);
  }
};

// A new temporary folder for table `name` (unique per process).
inline std::filesystem::path table_folder(const std::string& name) {
  static TableFolders folders;
  const auto d = std::filesystem::temp_directory_path() / fmt::format("agglo_outcome_table_{}_{}", name, ::getpid());
  std::filesystem::create_directories(d);
  folders.made.push_back(d);
  return d;
}

// Writes the dataset `d` (an outcome table) as table.nc into table_folder(name); returns its path.
inline std::filesystem::path write_table_dataset(const io::Dataset& d, const std::string& name) {
  const std::filesystem::path dir = table_folder(name);
  io::write_netcdf(OutputDir(dir), d, "table.nc");
  return dir / "table.nc";
}

// A monodisperse solid population of 1 um in the coagulation box with the constant kernel K = 1/N0
// (tau = K N0 t = t), 4000 samples of weight 2^20, steps of tau = 0.01, no motion, no energy
// compensation; `outcome_lines` go into [outcomes].
inline constexpr double kMonoN0 = 1048576.0 * 4000.0;

inline std::string constant_kernel_case(std::uint64_t seed, const std::string& outcome_lines, double end) {
  return fmt::format(R"(
seed = {}
{}
[time]
end = {}
collision_dt = 0.01
integrator = "none"
[[population]]
name = "mono"
phase = "solid"
distribution = "monodisperse"
diameter = 1e-6
number_concentration = {}
samples = 4000
[kernels]
model = "constant"
constant_coefficient = {}
[outcomes]
energy_compensation = false
{}
)",
                     seed, kCoagulationBox, end, kMonoN0, 1.0 / kMonoN0, outcome_lines);
}

// Solid spheres of 1 and 10 um (1e12 m^-3 each, `samples` samples each) in a 140 dB, 2 kHz wave, 100 cells,
// with the constant kernel `coefficient` [m^3/s], steps of 1e-4 s to `end` [s]: the 1-10 um pairs meet at
// normal speeds of 0-0.7 m/s, the equal-size pairs well below.
inline std::string two_size_wave_case(std::uint64_t seed, int samples, double end, double coefficient,
                                      bool energy_compensation) {
  return fmt::format(R"(
seed = {}
[gas]
gravity = false
[sound]
level_db = 140
frequency_hz = 2000
[domain]
cells_x = 100
[time]
end = {}
collision_dt = 1e-4
[[population]]
name = "fine"
phase = "solid"
distribution = "monodisperse"
diameter = 1e-6
number_concentration = 1e12
samples = {}
[[population]]
name = "coarse"
phase = "solid"
distribution = "monodisperse"
diameter = 10e-6
number_concentration = 1e12
samples = {}
[kernels]
model = "constant"
constant_coefficient = {}
[outcomes]
energy_compensation = {}
)",
                     seed, end, samples, samples, coefficient, energy_compensation);
}

// Mean over seeds and its standard error sqrt(sum (x - mean)^2 / ((n - 1) n)).
struct SeedMeanSe {
  double mean, se;
};
inline SeedMeanSe seed_mean_se(const std::vector<double>& x) {
  double m = 0, s = 0;
  for (double v : x) m += v;
  m /= static_cast<double>(x.size());
  for (double v : x) s += (v - m) * (v - m);
  return {m, std::sqrt(s / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()))};
}

}  // namespace agglo::acoustics::test
