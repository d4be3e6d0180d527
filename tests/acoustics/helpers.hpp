#pragma once
// Shared helpers of the acoustics tests: build an engine from an inline TOML case.
#include <cmath>
#include <string>

#include "agglo/acoustics/case_config.hpp"
#include "agglo/acoustics/engine.hpp"
#include "agglo/core/config.hpp"

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

// docs/model.md §C.7.3: mean orthokinetic kernel of fine sample f and droplet sample d in the wave [m^3/s],
//   <beta> = (pi/4)(d_d+d_f)^2 (2/pi) u_amp w |tau_d - tau_f| / sqrt((1 + w^2 tau_d^2)(1 + w^2 tau_f^2)).
inline double mean_orthokinetic_kernel(const Engine& e, std::size_t f, std::size_t d) {
  const SampleSet& p = e.particles();
  const double w = e.settings().motion.sound.omega, ua = e.settings().motion.sound.u_amp;
  const double tf = p.tau[f], td = p.tau[d], s = p.d[f] + p.d[d];
  return 0.25 * s * s * 2.0 * ua * w * std::abs(td - tf) / std::sqrt((1 + w * w * td * td) * (1 + w * w * tf * tf));
}

}  // namespace agglo::acoustics::test
