#pragma once
// Orthokinetic interaction + gravitational (differential) settling (docs/model.md §C.3, eq. 8):
//   beta = E (pi/4) (d_i + d_j)^2 |v_i - v_j|                                   [m^3/s]
// d diameter [m], v sample velocity [m/s], E collision efficiency (kernels.collision_efficiency).
// d of an aggregate is its collision diameter 2 R_c, its tau that of its mobility diameter (structure.hpp).
// Bound over the cell: |v_i - v_j| <= |v_i - v_ref| + max_j |v_j - v_ref|, d_j <= d_max. Bound over two
// groups a, b with reference velocities v_a, v_b: |v_i - v_j| <= |v_a - v_b| + max_a |v - v_a| + max_b |v - v_b|.
#include <cmath>
#include <string_view>

#include "agglo/acoustics/kernels/cell_bounds.hpp"
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/acoustics/sound.hpp"
#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

inline double beta_orthokinetic(double di, double dj, double rel_speed) {
  const double s = di + dj;
  return 0.25 * constants::pi * s * s * rel_speed;
}

struct Orthokinetic {
  static constexpr std::string_view name = "orthokinetic";
  double efficiency;  // E

  Orthokinetic(const KernelSettings& s, const Gas&, const Sound&) : efficiency(s.collision_efficiency) {}
  KernelNeeds needs() const { return {}; }
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double) const {
    const double gx = p.vx[i] - p.vx[j], gy = p.vy[i] - p.vy[j], gz = p.vz[i] - p.vz[j];
    return efficiency * beta_orthokinetic(p.d[i], p.d[j], std::sqrt(gx * gx + gy * gy + gz * gz));
  }
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const {
    const double ex = p.vx[i] - cb.vref[0], ey = p.vy[i] - cb.vref[1], ez = p.vz[i] - cb.vref[2];
    return efficiency * beta_orthokinetic(p.d[i], cb.d_max, std::sqrt(ex * ex + ey * ey + ez * ez) + cb.speed_dev_max);
  }
  double bound_cell(const CellBounds& cb) const {
    return efficiency * beta_orthokinetic(cb.d_max, cb.d_max, 2.0 * cb.speed_dev_max);
  }
  double bound_pair(const CellBounds& a, const CellBounds& b) const {
    const double gx = a.vref[0] - b.vref[0], gy = a.vref[1] - b.vref[1], gz = a.vref[2] - b.vref[2];
    const double g = std::sqrt(gx * gx + gy * gy + gz * gz) + a.speed_dev_max + b.speed_dev_max;
    return efficiency * beta_orthokinetic(a.d_max, b.d_max, g);
  }
};

}  // namespace agglo::acoustics
