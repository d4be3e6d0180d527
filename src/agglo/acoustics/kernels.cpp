#include "agglo/acoustics/kernels.hpp"

#include "agglo/core/error.hpp"

namespace agglo::acoustics {

void throw_unknown_mechanism(const std::string& name, const std::vector<std::string_view>& known) {
  std::string list;
  for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
  throw ConfigError("unknown kernel mechanism '" + name + "' (" + list + ")");
}

Kernel::Kernel(const KernelSettings& s, const Gas& gas, const Sound& sound)
    : s_(s), m_(mechanism_names(s), s, gas, sound) {}

double Kernel::beta(const SampleSet& p, std::size_t i, std::size_t j, double r) const { return m_.beta(p, i, j, r); }

double Kernel::bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const { return m_.bound(p, i, cb); }

double Kernel::bound_cell(const CellBounds& cb) const { return m_.bound_cell(cb); }

}  // namespace agglo::acoustics
