#include "agglo/acoustics/kernels/settings.hpp"

#include "agglo/acoustics/kernels/registry.hpp"

namespace agglo::acoustics {

std::string default_brownian_term() { return std::string(Brownian::name); }

std::vector<std::string> mechanism_names(const KernelSettings& s) {
  if (s.model != kAcousticModel) return {s.model};
  std::vector<std::string> names;
  if (s.orthokinetic) names.emplace_back(Orthokinetic::name);
  if (s.acoustic_wake) names.emplace_back(AcousticWake::name);
  if (s.radiation_pressure) names.emplace_back(RadiationPressure::name);
  if (s.brownian != kNoMechanism) names.push_back(s.brownian);
  return names;
}

std::vector<std::string> kernel_model_names() {
  std::vector<std::string> out{std::string(kAcousticModel)};
  for (auto n : KernelMechanisms::standalone_names()) out.emplace_back(n);
  return out;
}

std::vector<std::string> brownian_term_names() {
  std::vector<std::string> out{std::string(kNoMechanism)};
  for (auto n : KernelMechanisms::brownian_term_names()) out.emplace_back(n);
  return out;
}

}  // namespace agglo::acoustics
