#pragma once
// Shared helpers of the acoustics tests: build an engine from an inline TOML case.
#include <cmath>
#include <string>

#include "agglo/acoustics/case_config.hpp"
#include "agglo/acoustics/engine.hpp"
#include "agglo/core/config.hpp"
#include <fmt/format.h>

namespace agglo::acoustics::test {

inline AcousticCase parse_case(const std::string& toml) {
  Config cfg = Config::from_string(toml, "test.toml");
  return parse_acoustic_case(cfg);
}

inline Engine make_engine(const std::string& toml) { return Engine(parse_case(toml).engine); }

// Coagulation-only box of the kernel tests: no gravity, no sound, one 1 m^3 cell ([gas], [sound], [domain]);
// 298 K as PartMC's Brownian benchmark.
inline constexpr const char* kCoagulationBox = R"(
[gas]
gravity = false
temperature = 298.0
[sound]
enabled = false
[domain]
length_x = 1.0
length_y = 1.0
length_z = 1.0
cells_x = 1
min_cells_per_wavelength = 1
)";

// [time] and [kernels] of the constant-kernel tests: collisions only (no motion), steps of 0.1 ms to `end` [s]
// (`time_extra`: more [time] lines), K = 5e-10 m^3/s.
inline std::string constant_kernel_steps(const std::string& end, const std::string& time_extra = "") {
  return "[time]\nend = " + end + "\ncollision_dt = 1e-4\nintegrator = \"none\"\n" + time_extra +
         "[kernels]\nmodel = \"constant\"\nconstant_coefficient = 5e-10\n";
}

// Fractal soot: `samples` samples of a lognormal population around d_v = 0.2 um (sigma_g 1.8, 2e12 m^-3) with
// primaries of radius `primary_radius` [m]; the population's fractal-law lines follow it.
inline std::string soot_population(int samples, const std::string& primary_radius) {
  return "[[population]]\nname = \"soot\"\nphase = \"solid\"\ndistribution = \"lognormal\"\n"
         "geometric_mean_diameter = 2e-7\ngeometric_std = 1.8\nbins = 10\nnumber_concentration = 2e12\n"
         "samples = " + std::to_string(samples) + "\nstructure = \"fractal\"\nprimary_radius = " + primary_radius + "\n";
}

// One [[population]] section of the acoustics tests' cases. The doubles are written with an exponent, so the
// values parse as TOML floats exactly as typed in a case file.
struct Population {
  std::string name, phase;       // "fines" / "solid", "droplets" / "liquid", ...
  double diameter = 0.0;         // monodisperse diameter, or the lognormal geometric mean diameter [m]
  double concentration = 0.0;    // number concentration [1/m^3]
  long samples = 0;
  double geometric_std = 0.0;    // > 0: lognormal with this geometric standard deviation, else monodisperse
  int bins = 0;                  // lognormal bins (0: the default)
  std::string extra;             // more lines of the section (e.g. weight_rounding = "conserving")
};
inline std::string population(const Population& p) {
  std::string s = fmt::format("[[population]]\nname = \"{}\"\nphase = \"{}\"\n", p.name, p.phase);
  if (p.geometric_std > 0.0) {
    s += fmt::format("distribution = \"lognormal\"\ngeometric_mean_diameter = {:e}\ngeometric_std = {:e}\n",
                     p.diameter, p.geometric_std);
    if (p.bins > 0) s += fmt::format("bins = {}\n", p.bins);
  } else {
    s += fmt::format("distribution = \"monodisperse\"\ndiameter = {:e}\n", p.diameter);
  }
  s += fmt::format("number_concentration = {:e}\nsamples = {}\n", p.concentration, p.samples);
  return s + p.extra;
}
// A monodisperse population (diameter `d` [m], `n` [1/m^3]).
inline std::string monodisperse(const std::string& name, const std::string& phase, double d, double n, long samples,
                                const std::string& extra = "") {
  return population({name, phase, d, n, samples, 0.0, 0, extra});
}

// The `extra` line of a population whose sample weights are rounded conserving the number.
inline constexpr const char* kConserving = "weight_rounding = \"conserving\"\n";

// Solid fines, lognormal with geometric std 2, and monodisperse water droplets: the two populations of the
// paper's cases (`extra`: more lines of both sections).
inline std::string fines_and_droplets(double fine_dg, double fine_n, long fine_samples, int bins, double droplet_d,
                                      double droplet_n, long droplet_samples, const std::string& extra = "") {
  return population({"fines", "solid", fine_dg, fine_n, fine_samples, 2.0, bins, extra}) +
         population({"droplets", "liquid", droplet_d, droplet_n, droplet_samples, 0.0, 0, extra});
}

// The orthokinetic-only physics of the scavenging tests: no wake, radiation pressure, Brownian motion or
// inertia correction, no fine-fine collisions, and every fine that meets a droplet joins it.
inline constexpr const char* kOrthokineticOnly = R"(
[kernels]
acoustic_wake = false
radiation_pressure = false
brownian = false
inertia_correction = false
exclude_same_population = true
[outcomes]
always_coalesce = true
)";

// docs/model.md §C.7.3: mean orthokinetic kernel of fine sample f and droplet sample d in the wave [m^3/s],
//   <beta> = (pi/4)(d_d+d_f)^2 (2/pi) u_amp w |tau_d - tau_f| / sqrt((1 + w^2 tau_d^2)(1 + w^2 tau_f^2)).
inline double mean_orthokinetic_kernel(const Engine& e, std::size_t f, std::size_t d) {
  const SampleSet& p = e.particles();
  const double w = e.settings().motion.sound.omega, ua = e.settings().motion.sound.u_amp;
  const double tf = p.tau[f], td = p.tau[d], s = p.d[f] + p.d[d];
  return 0.25 * s * s * 2.0 * ua * w * std::abs(td - tf) / std::sqrt((1 + w * w * td * td) * (1 + w * w * tf * tf));
}

// Solid fines (lognormal, geometric std 2) and 30 um water droplets in a 150 dB, 2 kHz standing wave,
// 20 cells along x, 60 steps of 2.5e-5 s (Nanbu selection, exact integrator), then `output` (the
// [output] section and anything after it).
struct WaveCase {
  int seed = 7;
  double fines_diameter = 0.5e-6, fines_concentration = 5e12;  // [m], [1/m^3]
  int fines_samples = 1500;
  double droplet_concentration = 5e10;  // [1/m^3]
  int droplet_samples = 200;
};
inline std::string standing_wave_case(const WaveCase& w, const std::string& output) {
  return fmt::format(R"(
seed = {}
[sound]
level_db = 150.0
frequency_hz = 2000.0
[domain]
length_y = 0.002
length_z = 0.002
cells_x = 20
min_cells_per_wavelength = 1
[time]
end = 1.5e-3
collision_dt = 2.5e-5
motion_dt = 2.5e-5

)", w.seed) + fines_and_droplets(w.fines_diameter, w.fines_concentration, w.fines_samples, 0, 30e-6,
                                  w.droplet_concentration, w.droplet_samples) + output;
}

// Number concentration of the samples: the sum of their weights [m^-3].
inline double total_number(const SampleSet& p) {
  double n = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) n += p.w[i];
  return n;
}

}  // namespace agglo::acoustics::test
