#include "agglo/acoustics/kernels/cell_bounds.hpp"

#include <algorithm>

#include "agglo/acoustics/kernels/brownian_fuchs.hpp"

namespace agglo::acoustics {

void CellBounds::include(const SampleSet& p, std::size_t i, const Gas& gas) {
  d_max = std::max(d_max, p.d[i]);
  d_min = d_min == 0.0 ? p.d[i] : std::min(d_min, p.d[i]);
  mass_max = std::max(mass_max, p.mass[i]);
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
  // The thermal speed decreases with the mass (correctly rounded division and sqrt keep that exactly), so
  // the largest one is that of the lightest particle: one sqrt per new minimum instead of one per sample.
  if (need_cbar && (mass_min == 0.0 || p.mass[i] < mass_min)) {
    mass_min = p.mass[i];
    cbar_max = std::max(cbar_max, thermal_speed(gas, mass_min));
  }
}

}  // namespace agglo::acoustics
