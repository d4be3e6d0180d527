#pragma once
// Shared helpers of the outcome-table tests (test_outcome_table.cpp, test_wet_outcome_table.cpp,
// test_breakage.cpp, test_fragment_distribution.cpp): tables built in memory (constant, or a closed-form
// critical velocity), table files in temporary folders, the constant-kernel box and seed statistics.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/core/error.hpp"
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

// n nodes from lo to hi, equally spaced in log.
inline std::vector<double> log_axis(double lo, double hi, int n) {
  std::vector<double> a;
  for (int k = 0; k < n; ++k) a.push_back(lo * std::pow(hi / lo, n > 1 ? static_cast<double>(k) / (n - 1) : 0.0));
  return a;
}

// A table with P_stick = f(v, d1, d2) at the nodes, P_bounce = 1 - P_stick, P_break = 0.
inline OutcomeTable table_of(std::vector<double> v, std::vector<double> d1, std::vector<double> d2,
                             const std::function<double(double, double, double)>& f) {
  OutcomeTable t;
  t.axes = {std::move(v), std::move(d1), std::move(d2)};
  for (double a : t.axes[0])
    for (double b : t.axes[1])
      for (double c : t.axes[2]) {
        t.p_stick.push_back(f(a, b, c));
        t.p_bounce.push_back(1.0 - t.p_stick.back());
        t.p_break.push_back(0.0);
      }
  return t;
}

// A table of a closed-form critical velocity v_cr(d1, d2) [m/s]: P_stick = 1 at the nodes with v <= v_cr,
// else 0 (bounce); 500 speeds over 1e-3-10 m/s, 20 diameters per decade over 0.5-40 um (the interpolation
// ramp between two speed nodes spans 1.9 % of v_cr).
inline OutcomeTable critical_velocity_table(const std::function<double(double, double)>& v_cr) {
  return table_of(log_axis(1e-3, 10.0, 500), log_axis(0.5e-6, 40e-6, 39), log_axis(0.5e-6, 40e-6, 39),
                  [&](double v, double a, double b) { return v <= v_cr(a, b) ? 1.0 : 0.0; });
}

// A table file of constant P_stick = alpha (P_bounce = 1 - alpha) over 1e-3-10 m/s and 0.1-100 um.
inline std::string constant_table_file(double alpha, const std::string& name) {
  const OutcomeTable t =
      table_of({1e-3, 10.0}, {1e-7, 1e-4}, {1e-7, 1e-4}, [alpha](double, double, double) { return alpha; });
  return write_table_dataset(outcome_table_dataset(t), name).string();
}

// A table of constant P_stick = stick, P_break = brk (P_bounce the rest) and fragment statistics f over
// 1e-4-100 m/s and 1 nm-1 mm.
inline OutcomeTable constant_break_table(double stick, double brk, FragmentStats f) {
  OutcomeTable t;
  t.axes = {std::vector<double>{1e-4, 100.0}, std::vector<double>{1e-9, 1e-3}, std::vector<double>{1e-9, 1e-3}};
  const std::size_t n = 8;
  t.p_stick.assign(n, stick);
  t.p_break.assign(n, brk);
  t.p_bounce.assign(n, 1.0 - stick - brk);
  t.fragments.assign(n, f.number);
  t.largest_fraction.assign(n, f.largest);
  return t;
}

// Runs engine e to its end: the number of real particles (sum of the weights) at the end.
inline double run_counting(Engine& e) {
  while (e.time() < e.settings().t_end - 1e-9) e.step();
  double n = 0;
  for (std::size_t i = 0; i < e.particles().size(); ++i) n += e.particles().w[i];
  return n;
}
inline double number_at_end(const std::string& toml) {
  Engine e = make_engine(toml);
  return run_counting(e);
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

// The constant-kernel case (seed 1, to tau = 0.1) with `outcome_lines` in [outcomes] must be refused
// (ConfigError) with `needle` in its message.
inline void expect_case_refused(const std::string& outcome_lines, const std::string& needle) {
  try {
    (void)parse_case(constant_kernel_case(1, outcome_lines, 0.1));
    ADD_FAILURE() << "accepted: " << outcome_lines;
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
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
