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

namespace {
// Scaled source of one order m (AxialTranslation::apply): x[2(n-m)], x[2(n-m)+1] = s_n v^(n+1) (beta_nm,
// beta_n,-m), s_n = -1 for odd n when the source is at -t z.
// vp0 = v^(m+1) (std::pow).
void translation_source(int Lmax, int m, double v, double vp0, int sign, const double* in, double* x) {
  double vp = vp0;
  for (int n = m; n <= Lmax; ++n) {
    double s = (sign < 0 && (n & 1)) ? -vp : vp;
    x[2 * (n - m)] = s * in[idx(n, m)];
    x[2 * (n - m) + 1] = (m > 0) ? s * in[idx(n, -m)] : 0.0;
    vp *= v;
  }
}
// out += the target scaling s_j u^j of y (up: powers of u); with add = false out = it.
void translation_target(int Lmax, int m, const double* up, int sign, const double* y, double* out, bool add = true) {
  for (int j = m; j <= Lmax; ++j) {
    double s = (sign < 0 && (j & 1)) ? -up[j] : up[j];
    const double a = add ? out[idx(j, m)] : 0.0;
    out[idx(j, m)] = a + s * y[2 * (j - m)];
    if (m > 0) out[idx(j, -m)] = (add ? out[idx(j, -m)] : 0.0) + s * y[2 * (j - m) + 1];
  }
}
}  // namespace

void AxialTranslation::apply(int Lmax, int Mmax, double u, double v, int sign, const double* in, double* out) const {
  double up[1024];
  double p = 1.0;
  for (int j = 0; j <= Lmax; ++j) {
    up[j] = p;
    p *= u;
  }
  alignas(16) double x[2 * 1024], y[2 * 1024];
  for (int m = 0; m <= std::min(Lmax, Mmax); ++m) {
    const int nn = Lmax - m + 1;
    translation_source(Lmax, m, v, std::pow(v, m + 1), sign, in, x);
    kern::gemv2(&f_[off_[m]], L_ - m + 1, nn, nn, x, y);
    translation_target(Lmax, m, up, sign, y, out);
  }
}

void AxialTranslation::source_powers(int Mmax, double u, double v, std::vector<double>& powers) {
  powers.resize(2 * std::size_t(Mmax + 1));
  for (int m = 0; m <= Mmax; ++m) {
    powers[2 * m] = std::pow(v, m + 1);
    powers[2 * m + 1] = std::pow(u, m + 1);
  }
}

void AxialTranslation::apply_pair(int Lmax, int Mmax, double u, double v, const double* in_b, const double* in_a,
                                  double* out_a, double* out_b, const double* powers, bool add) const {
  double pu[1024], pv[1024];
  double p = 1.0, q = 1.0;
  for (int j = 0; j <= Lmax; ++j) {
    pu[j] = p;
    pv[j] = q;
    p *= u;
    q *= v;
  }
  alignas(16) double x[2 * 1024], y[2 * 1024], x2[2 * 1024], y2[2 * 1024];
  for (int m = 0; m <= std::min(Lmax, Mmax); ++m) {
    const int nn = Lmax - m + 1;
    translation_source(Lmax, m, v, powers ? powers[2 * m] : std::pow(v, m + 1), +1, in_b, x);
    translation_source(Lmax, m, u, powers ? powers[2 * m + 1] : std::pow(u, m + 1), -1, in_a, x2);
    kern::gemv2x2(&f_[off_[m]], L_ - m + 1, nn, nn, x, x2, y, y2);
    translation_target(Lmax, m, pu, +1, y, out_a, add);
    translation_target(Lmax, m, pv, -1, y2, out_b, add);
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
