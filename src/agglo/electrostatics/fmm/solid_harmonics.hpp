#pragma once
// Complex solid harmonics for the Laplace kernel 1/|x| (Helgaker et al., "Molecular
// Electronic-Structure Theory", sec. 9.13 normalisation; Legendre functions with the
// Condon-Shortley phase):
//   regular    R_n^m(x) = r^n P_n^m(cos t) e^{i m p} / (n+m)!
//   irregular  I_n^m(x) = (n-m)! P_n^m(cos t) e^{i m p} / r^{n+1}
//   negative m: X_n^{-m} = (-1)^m conj(X_n^m).
// Identities used by the FMM (all verified in tests/electrostatics/test_fmm_harmonics.cpp):
//   R_n^m(a+b)   = sum_{k,l} R_k^l(a) R_{n-k}^{m-l}(b)                 (addition theorem)
//   1/|x-y|      = sum_{n,m} conj(R_n^m(y)) I_n^m(x),            |y| < |x|
//   I_n^m(D+z)   = sum_{k,l} (-1)^k conj(R_k^l(z)) I_{n+k}^{m+l}(D), |z| < |D|
// Storage: triangular, m >= 0 only, index tri(n,m) = n(n+1)/2 + m.
#include <complex>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::es::fmm {

using cplx = std::complex<double>;

constexpr int tri(int n, int m) { return n * (n + 1) / 2 + m; }
constexpr int tri_size(int p) { return (p + 1) * (p + 2) / 2; }

// R_n^m(x) for 0 <= m <= n <= p into out[tri(n,m)] (out must hold tri_size(p)).
void regular_harmonics(const Vec3& x, int p, cplx* out);
// I_n^m(x) for 0 <= m <= n <= p into out[tri(n,m)]; x != 0.
void irregular_harmonics(const Vec3& x, int p, cplx* out);

// Coefficient with any sign of m from m >= 0 storage (zero when |m| > n).
inline cplx coeff(const cplx* a, int n, int m) {
  if (m > n || -m > n) return {0.0, 0.0};
  if (m >= 0) return a[tri(n, m)];
  const cplx c = std::conj(a[tri(n, -m)]);
  return (m & 1) ? -c : c;
}

}  // namespace agglo::es::fmm
