#include "agglo/acoustics/kernels/cell_bounds.hpp"

#include <algorithm>

#include "agglo/acoustics/kernels/brownian_fuchs.hpp"

namespace agglo::acoustics {

void CellBounds::include(const SampleSet& p, std::size_t i, const Gas& gas) {
  d_max = std::max(d_max, p.d[i]);
  vol_max = std::max(vol_max, p.volume(i));
  dl_max = std::max(dl_max, p.dl[i]);
  ccd_max = std::max(ccd_max, p.ccd[i]);
  w_max = std::max(w_max, p.w[i]);
  const double ex = p.vx[i] - vref[0], ey = p.vy[i] - vref[1], ez = p.vz[i] - vref[2];
  const double s2 = ex * ex + ey * ey + ez * ez;
  if (s2 > speed_dev2_max) {
    speed_dev2_max = s2;
    speed_dev_max = std::sqrt(s2);
  }
  if (need_cbar) cbar_max = std::max(cbar_max, thermal_speed(gas, p.mass[i]));
}

}  // namespace agglo::acoustics
