#pragma once
// Additive test kernel (docs/model.md §C.7.1): beta = B (v_i + v_j) [m^3/s], v particle volume [m^3],
// B [1/s] (kernels.additive_coefficient). Bound over the cell: B (v_i + max v); over groups a, b: B (max_a v + max_b v).
#include <string_view>

#include "agglo/acoustics/kernels/cell_bounds.hpp"
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/acoustics/sound.hpp"

namespace agglo::acoustics {

struct AdditiveKernel {
  static constexpr std::string_view name = "additive";
  static constexpr bool standalone = true;
  double b;  // B [1/s]

  AdditiveKernel(const KernelSettings& s, const Gas&, const Sound&) : b(s.additive_coefficient) {}
  KernelNeeds needs() const { return {.volume = true}; }
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double) const {
    return b * (p.volume(i) + p.volume(j));
  }
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const { return b * (p.volume(i) + cb.vol_max); }
  double bound_cell(const CellBounds& cb) const { return b * 2.0 * cb.vol_max; }
  double bound_pair(const CellBounds& a, const CellBounds& c) const { return b * (a.vol_max + c.vol_max); }
};

}  // namespace agglo::acoustics
