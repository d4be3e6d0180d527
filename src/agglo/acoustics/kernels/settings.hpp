#pragma once
// Kernel selection of a case ([kernels] keys, keys.hpp): the model, and for the acoustic model which
// of its terms are summed (docs/model.md §C.3). Turned into mechanism names by mechanism_names().
// Every name is the one a mechanism declares (registry.hpp); "acoustic" names the sum of the terms.
#include <string>
#include <string_view>
#include <vector>

namespace agglo::acoustics {

inline constexpr std::string_view kAcousticModel = "acoustic";  // kernels.model: the sum of the terms below
inline constexpr std::string_view kNoMechanism = "none";        // kernels.brownian: no Brownian term

// The Brownian term of the acoustic sum when a case names none (kernels.brownian default).
std::string default_brownian_term();

struct KernelSettings {
  std::string model{kAcousticModel};  // kAcousticModel, or one mechanism alone (kernels.model)
  bool orthokinetic = true;           // beta_OI+GS
  bool acoustic_wake = true;          // beta_AWE
  bool radiation_pressure = true;     // beta_MRPE
  std::string brownian = default_brownian_term();  // beta_BD: a Brownian mechanism, or kNoMechanism
  double collision_efficiency = 1.0;  // multiplies beta_OI+GS
  double constant_coefficient = 0.0;  // K0 [m^3/s]
  double additive_coefficient = 0.0;  // B [1/s]
  bool exclude_same_population = false;  // test switch: only pairs of different populations collide
};

// Names of the registered mechanisms (kernels/registry.hpp) the settings switch on: the model alone,
// or for the acoustic model the enabled ones of orthokinetic, acoustic_wake, radiation_pressure and
// the Brownian term.
std::vector<std::string> mechanism_names(const KernelSettings& s);

// The names kernels.model and kernels.brownian accept: kAcousticModel and the mechanisms declaring
// `standalone`; kNoMechanism and those declaring `brownian_term` (mechanism_set.hpp).
std::vector<std::string> kernel_model_names();
std::vector<std::string> brownian_term_names();

}  // namespace agglo::acoustics
