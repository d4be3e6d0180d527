#include "agglo/electrostatics/spectral/translation.hpp"

#include <cmath>

#include "agglo/electrostatics/spectral/harmonics.hpp"

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

void AxialTranslation::apply(int Lmax, double u, double v, int sign, const double* in, double* out) const {
  double xc[1024], xs[1024], up[1024];
  double p = 1.0;
  for (int j = 0; j <= Lmax; ++j) {
    up[j] = p;
    p *= u;
  }
  for (int m = 0; m <= Lmax; ++m) {
    const int w = L_ - m + 1;
    const int nn = Lmax - m + 1;
    const double* F = &f_[off_[m]];
    // scaled source: v^(n+1) beta_n (and the (-1)^n of a source at -t z)
    double vp = std::pow(v, m + 1);
    for (int n = m; n <= Lmax; ++n) {
      double s = (sign < 0 && (n & 1)) ? -vp : vp;
      xc[n - m] = s * in[idx(n, m)];
      xs[n - m] = (m > 0) ? s * in[idx(n, -m)] : 0.0;
      vp *= v;
    }
    for (int j = m; j <= Lmax; ++j) {
      const double* row = F + (j - m) * w;
      double ac = 0.0, as = 0.0;
      if (m > 0) {
        for (int k = 0; k < nn; ++k) {
          ac += row[k] * xc[k];
          as += row[k] * xs[k];
        }
      } else {
        for (int k = 0; k < nn; ++k) ac += row[k] * xc[k];
      }
      double s = (sign < 0 && (j & 1)) ? -up[j] : up[j];
      out[idx(j, m)] += s * ac;
      if (m > 0) out[idx(j, -m)] += s * as;
    }
  }
}

}  // namespace agglo::es::sh
