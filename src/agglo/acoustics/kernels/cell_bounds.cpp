#include "agglo/acoustics/kernels/cell_bounds.hpp"

#include <algorithm>

#include "agglo/acoustics/kernels/brownian_fuchs.hpp"

namespace agglo::acoustics {

namespace {

// The bounds of cb extended by the samples index(0) .. index(n-1), in that order, with the maxima in
// registers: include() is n = 1, include_all() a whole group (one body, so the two agree bit for bit).
template <class Index>
void include_samples(CellBounds& cb, const SampleSet& p, std::size_t n, const Index& index, const Gas& gas) {
  double dmax = cb.d_max, dmin = cb.d_min, mmax = cb.mass_max, vmax = cb.vol_max, dlmax = cb.dl_max;
  double ccdmax = cb.ccd_max, wmax = cb.w_max, s2max = cb.speed_dev2_max;
  const double r0 = cb.vref[0], r1 = cb.vref[1], r2 = cb.vref[2];
  bool new_speed = false;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = index(k);
    const double d = p.d[i], m = p.mass[i];
    dmax = std::max(dmax, d);
    dmin = dmin == 0.0 ? d : std::min(dmin, d);
    mmax = std::max(mmax, m);
    vmax = std::max(vmax, p.volume(i));
    dlmax = std::max(dlmax, p.dl[i]);
    ccdmax = std::max(ccdmax, p.ccd[i]);
    wmax = std::max(wmax, p.w[i]);
    const double ex = p.vx[i] - r0, ey = p.vy[i] - r1, ez = p.vz[i] - r2;
    const double s2 = ex * ex + ey * ey + ez * ez;
    if (s2 > s2max) {
      s2max = s2;
      new_speed = true;
    }
    // The thermal speed decreases with the mass (correctly rounded division and sqrt keep that exactly), so
    // the largest one is that of the lightest particle: one sqrt per new minimum instead of one per sample.
    if (cb.need_cbar && (cb.mass_min == 0.0 || m < cb.mass_min)) {
      cb.mass_min = m;
      cb.cbar_max = std::max(cb.cbar_max, thermal_speed(gas, cb.mass_min));
    }
  }
  cb.d_max = dmax;
  cb.d_min = dmin;
  cb.mass_max = mmax;
  cb.vol_max = vmax;
  cb.dl_max = dlmax;
  cb.ccd_max = ccdmax;
  cb.w_max = wmax;
  cb.speed_dev2_max = s2max;
  if (new_speed) cb.speed_dev_max = std::sqrt(s2max);  // the root of the largest square
}

}  // namespace

void CellBounds::include(const SampleSet& p, std::size_t i, const Gas& gas) {
  include_samples(*this, p, 1, [i](std::size_t) { return i; }, gas);
}

void CellBounds::include_all(const SampleSet& p, const std::uint32_t* idx, const std::uint32_t* members,
                             std::size_t n, const Gas& gas) {
  include_samples(*this, p, n, [&](std::size_t k) { return std::size_t{idx[members[k]]}; }, gas);
}

}  // namespace agglo::acoustics
