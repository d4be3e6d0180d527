#include "agglo/electrostatics/spectral/translation.hpp"

#include <algorithm>
#include <cmath>


#include "agglo/electrostatics/spectral/harmonics.hpp"
#include "agglo/electrostatics/spectral/dense_ops.hpp"

namespace agglo::es::sh {

void AxialTranslation::prepare(int L) {
  if (L == L_) return;
  L_ = L;
  off_.assign(L + 2, 0);
  for (int m = 0; m <= L; ++m) off_[m + 1] = off_[m] + (L - m + 1) * (L - m + 1);
  f_.assign(off_[L + 1], 0.0);
  for (int m = 0; m <= L; ++m) {
    const int w = L - m + 1;
    for (int j = m; j <= L; ++j)
      for (int n = m; n <= L; ++n) {
        double lf = std::lgamma(j + n + 1.0) -
                    0.5 * (std::lgamma(j - m + 1.0) + std::lgamma(j + m + 1.0) + std::lgamma(n - m + 1.0) +
                           std::lgamma(n + m + 1.0));
        double v = std::exp(lf);
        if ((m + n) & 1) v = -v;
        f_[off_[m] + (j - m) * w + (n - m)] = v;
      }
  }
}

void AxialTranslation::apply(int Lmax, int Mmax, double u, double v, int sign, const double* in, double* out) const {
  double up[1024];
  double p = 1.0;
  for (int j = 0; j <= Lmax; ++j) {
    up[j] = p;
    p *= u;
  }
  for (int m = 0; m <= std::min(Lmax, Mmax); ++m) {
    const int w = L_ - m + 1;
    const int nn = Lmax - m + 1;
    const double* F = &f_[off_[m]];
    // scaled source: v^(n+1) beta_n (and the (-1)^n of a source at -t z)
    double vp = std::pow(v, m + 1);
    alignas(16) double x[2 * 1024], y[2 * 1024];
    for (int n = m; n <= Lmax; ++n) {
      double s = (sign < 0 && (n & 1)) ? -vp : vp;
      x[2 * (n - m)] = s * in[idx(n, m)];
      x[2 * (n - m) + 1] = (m > 0) ? s * in[idx(n, -m)] : 0.0;
      vp *= v;
    }
    kern::gemv2(F, w, nn, nn, x, y);
    for (int j = m; j <= Lmax; ++j) {
      double s = (sign < 0 && (j & 1)) ? -up[j] : up[j];
      out[idx(j, m)] += s * y[2 * (j - m)];
      if (m > 0) out[idx(j, -m)] += s * y[2 * (j - m) + 1];
    }
  }
}

}  // namespace agglo::es::sh

namespace agglo::es::sh {

int AxialTranslation::order_cutoff(int Lmax, double u, double v, double tol) const {
  // bound of the m-block operator norm: (block size) * max |F u^j v^(n+1)|, both directions
  std::vector<double> lu(Lmax + 2), lv(Lmax + 2);
  for (int k = 0; k <= Lmax + 1; ++k) {
    lu[k] = std::pow(u, k);
    lv[k] = std::pow(v, k);
  }
  for (int m = Lmax; m > 0; --m) {
    const int w = L_ - m + 1;
    const double* F = &f_[off_[m]];
    double mx = 0.0;
    for (int j = m; j <= Lmax; ++j)
      for (int n = m; n <= Lmax; ++n) {
        double f = std::abs(F[(j - m) * w + (n - m)]);
        mx = std::max(mx, f * std::max(lu[j] * lv[n + 1], lv[j] * lu[n + 1]));
      }
    if (mx * (Lmax - m + 1) >= tol) return m;
  }
  return 0;
}

}  // namespace agglo::es::sh
