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

void CellBounds::include_all(const SampleSet& p, const std::uint32_t* idx, const std::uint32_t* members,
                             std::size_t n, const Gas& gas) {
  double dmax = d_max, dmin = d_min, mmax = mass_max, vmax = vol_max, dlmax = dl_max, ccdmax = ccd_max;
  double wmax = w_max, s2max = speed_dev2_max;
  const double r0 = vref[0], r1 = vref[1], r2 = vref[2];
  bool new_speed = false;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = idx[members[k]];
    const double d = p.d[i], m = p.mass[i];
    dmax = std::max(dmax, d);
    dmin = dmin == 0.0 ? d : std::min(dmin, d);
    mmax = std::max(mmax, m);
    vmax = std::max(vmax, p.vol_s[i] + p.vol_l[i]);
    dlmax = std::max(dlmax, p.dl[i]);
    ccdmax = std::max(ccdmax, p.ccd[i]);
    wmax = std::max(wmax, p.w[i]);
    const double ex = p.vx[i] - r0, ey = p.vy[i] - r1, ez = p.vz[i] - r2;
    const double s2 = ex * ex + ey * ey + ez * ez;
    if (s2 > s2max) {
      s2max = s2;
      new_speed = true;
    }
    if (need_cbar && (mass_min == 0.0 || m < mass_min)) {  // rare: a new lightest member (include())
      mass_min = m;
      cbar_max = std::max(cbar_max, thermal_speed(gas, mass_min));
    }
  }
  d_max = dmax;
  d_min = dmin;
  mass_max = mmax;
  vol_max = vmax;
  dl_max = dlmax;
  ccd_max = ccdmax;
  w_max = wmax;
  speed_dev2_max = s2max;
  if (new_speed) speed_dev_max = std::sqrt(s2max);  // include() sets it at every new largest square
}

}  // namespace agglo::acoustics
