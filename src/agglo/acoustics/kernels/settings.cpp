#include "agglo/acoustics/kernels/settings.hpp"

#include "agglo/core/error.hpp"

namespace agglo::acoustics {

KernelModel kernel_model_from_name(const std::string& n) {
  if (n == "acoustic") return KernelModel::acoustic;
  if (n == "constant") return KernelModel::constant;
  if (n == "additive") return KernelModel::additive;
  if (n == "brownian_fuchs") return KernelModel::brownian_fuchs;
  if (n == "brownian_partmc") return KernelModel::brownian_partmc;
  throw ConfigError("unknown kernel model '" + n + "' (acoustic, constant, additive, brownian_fuchs, brownian_partmc)");
}

const char* kernel_model_name(KernelModel m) {
  switch (m) {
    case KernelModel::acoustic: return "acoustic";
    case KernelModel::constant: return "constant";
    case KernelModel::additive: return "additive";
    case KernelModel::brownian_fuchs: return "brownian_fuchs";
    case KernelModel::brownian_partmc: return "brownian_partmc";
  }
  return "?";
}

std::vector<std::string> mechanism_names(const KernelSettings& s) {
  if (s.model != KernelModel::acoustic) return {kernel_model_name(s.model)};
  std::vector<std::string> names;
  if (s.orthokinetic) names.emplace_back("orthokinetic");
  if (s.acoustic_wake) names.emplace_back("acoustic_wake");
  if (s.radiation_pressure) names.emplace_back("radiation_pressure");
  if (s.brownian) names.emplace_back("brownian");
  return names;
}

}  // namespace agglo::acoustics
