#pragma once
// Acoustic wake effect (docs/model.md §C.3, eq. 9):
//   beta = (3/16) (u_amp / r) (d_i + d_j)^2 (d_i l_i + d_j l_j)                 [m^3/s]
// u_amp gas velocity amplitude [m/s], r centre distance [m] floored at contact (d_i + d_j)/2,
// l = omega tau / sqrt(1 + (omega tau)^2) slip coefficient.
// d of an aggregate is its collision diameter 2 R_c, its tau that of its mobility diameter (structure.hpp).
// Bound over the cell: with r >= (d_i + d_j)/2, beta <= (3/8) u_amp (d_i + d_j)(d_i l_i + max d l); over two
// groups a, b: (3/8) u_amp (max_a d + max_b d)(max_a d l + max_b d l).
#include <algorithm>
#include <string_view>

#include "agglo/acoustics/kernels/cell_bounds.hpp"
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/acoustics/sound.hpp"

namespace agglo::acoustics {

inline double beta_acoustic_wake(double u_amp, double r, double di, double dj, double li, double lj) {
  const double s = di + dj;
  r = std::max(r, 0.5 * s);
  return 0.1875 * (u_amp / r) * s * s * (di * li + dj * lj);
}

struct AcousticWake {
  static constexpr std::string_view name = "acoustic_wake";
  double u_amp;  // [m/s]

  AcousticWake(const KernelSettings&, const Gas&, const Sound& sound) : u_amp(sound.u_amp) {}
  KernelNeeds needs() const { return {.distance = true}; }
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double r) const {
    return beta_acoustic_wake(u_amp, r, p.d[i], p.d[j], p.slip_l[i], p.slip_l[j]);
  }
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const {
    return 0.375 * u_amp * (p.d[i] + cb.d_max) * (p.dl[i] + cb.dl_max);
  }
  double bound_cell(const CellBounds& cb) const { return 0.375 * u_amp * (2.0 * cb.d_max) * 2.0 * cb.dl_max; }
  double bound_pair(const CellBounds& a, const CellBounds& b) const {
    return 0.375 * u_amp * (a.d_max + b.d_max) * (a.dl_max + b.dl_max);
  }
};

}  // namespace agglo::acoustics
