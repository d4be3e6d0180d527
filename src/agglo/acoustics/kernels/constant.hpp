#pragma once
// Constant test kernel (docs/model.md §C.7.1): beta = K0 [m^3/s] (kernels.constant_coefficient).
// Bound (per sample, cell or pair of groups): K0.
#include <string_view>

#include "agglo/acoustics/kernels/cell_bounds.hpp"
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/acoustics/sound.hpp"

namespace agglo::acoustics {

struct ConstantKernel {
  static constexpr std::string_view name = "constant";
  static constexpr bool standalone = true;
  double k0;  // K0 [m^3/s]

  ConstantKernel(const KernelSettings& s, const Gas&, const Sound&) : k0(s.constant_coefficient) {}
  KernelNeeds needs() const { return {}; }
  double beta(const SampleSet&, std::size_t, std::size_t, double) const { return k0; }
  double bound(const SampleSet&, std::size_t, const CellBounds&) const { return k0; }
  double bound_cell(const CellBounds&) const { return k0; }
  double bound_pair(const CellBounds&, const CellBounds&) const { return k0; }
};

}  // namespace agglo::acoustics
