#include "agglo/electrostatics/fmm/solid_harmonics.hpp"

namespace agglo::es::fmm {

void regular_harmonics(const Vec3& x, int p, cplx* out) {
  const double r2 = norm2(x);
  const cplx xy(x.x, x.y);
  cplx diag(1.0, 0.0);  // R_m^m
  for (int m = 0; m <= p; ++m) {
    if (m > 0) diag *= -xy / (2.0 * m);
    out[tri(m, m)] = diag;
    if (m == p) break;
    out[tri(m + 1, m)] = x.z * diag;
    for (int l = m + 1; l < p; ++l)
      out[tri(l + 1, m)] = ((2.0 * l + 1.0) * x.z * out[tri(l, m)] - r2 * out[tri(l - 1, m)]) /
                           (double((l + m + 1) * (l - m + 1)));
  }
}

void irregular_harmonics(const Vec3& x, int p, cplx* out) {
  const double r2 = norm2(x);
  const double inv_r2 = 1.0 / r2;
  const cplx xy(x.x, x.y);
  cplx diag(1.0 / std::sqrt(r2), 0.0);  // I_m^m
  for (int m = 0; m <= p; ++m) {
    if (m > 0) diag *= -(2.0 * m - 1.0) * xy * inv_r2;
    out[tri(m, m)] = diag;
    if (m == p) break;
    out[tri(m + 1, m)] = (2.0 * m + 1.0) * x.z * inv_r2 * diag;
    for (int l = m + 1; l < p; ++l)
      out[tri(l + 1, m)] =
          ((2.0 * l + 1.0) * x.z * out[tri(l, m)] - double(l * l - m * m) * out[tri(l - 1, m)]) * inv_r2;
  }
}

}  // namespace agglo::es::fmm
