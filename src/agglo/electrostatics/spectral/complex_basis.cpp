#include "agglo/electrostatics/spectral/complex_basis.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/electrostatics/spectral/harmonics.hpp"

namespace agglo::es::sh {

ComplexBasis::ComplexBasis(int p) : p_(p), s_(fmm::tri_size(p)) {
  for (int n = 0; n <= p; ++n)
    for (int m = 0; m <= n; ++m) {
      const double v = std::exp(-0.5 * (std::lgamma(n - m + 1.0) + std::lgamma(n + m + 1.0)));
      s_[fmm::tri(n, m)] = (m & 1) ? -v : v;
    }
}

void ComplexBasis::multipole_from_real(int L, double rho, const double* beta, fmm::cplx* M) const {
  std::fill(M, M + fmm::tri_size(p_), fmm::cplx(0.0, 0.0));
  double rn = rho;  // rho^(n+1)
  for (int n = 0; n <= std::min(p_, L); ++n, rn *= rho) {
    M[fmm::tri(n, 0)] = s_[fmm::tri(n, 0)] * rn * beta[idx(n, 0)];
    for (int m = 1; m <= n; ++m) {
      const double f = 0.5 * s_[fmm::tri(n, m)] * rn;
      M[fmm::tri(n, m)] = fmm::cplx(f * beta[idx(n, m)], -f * beta[idx(n, -m)]);
    }
  }
}

void ComplexBasis::add_real_local(int L, double rho, const fmm::cplx* Lc, double* alpha) const {
  double rn = 1.0;  // rho^n
  for (int n = 0; n <= std::min(p_, L); ++n, rn *= rho) {
    alpha[idx(n, 0)] += s_[fmm::tri(n, 0)] * rn * Lc[fmm::tri(n, 0)].real();
    for (int m = 1; m <= n; ++m) {
      const double f = 2.0 * s_[fmm::tri(n, m)] * rn;
      alpha[idx(n, m)] += f * Lc[fmm::tri(n, m)].real();
      alpha[idx(n, -m)] -= f * Lc[fmm::tri(n, m)].imag();
    }
  }
}

}  // namespace agglo::es::sh
