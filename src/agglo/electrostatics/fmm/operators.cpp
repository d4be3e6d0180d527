#include "agglo/electrostatics/fmm/operators.hpp"

#include <algorithm>

namespace agglo::es::fmm {

namespace {

// Plain complex product (std::complex operator* goes through __muldc3 without -ffast-math).
inline cplx mul(const cplx& a, const cplx& b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

}  // namespace

OperatorScratch::OperatorScratch(int p)
    : R(tri_size(p)), I(tri_size(p)), Ire((p + 1) * (p + 1)), Iim((p + 1) * (p + 1)) {}

void p2m(const Points& pts, int begin, int end, const double* q, const Vec3& center, int p, cplx* M,
         OperatorScratch& s) {
  const int ts = tri_size(p);
  for (int k = begin; k < end; ++k) {
    regular_harmonics(Vec3{pts.x[k], pts.y[k], pts.z[k]} - center, p, s.R.data());
    for (int i = 0; i < ts; ++i) M[i] += q[k] * std::conj(s.R[i]);
  }
}

void m2m(const cplx* M_child, const Vec3& shift, int p, cplx* M_parent, OperatorScratch& s) {
  const cplx* R = s.R.data();
  regular_harmonics(shift, p, s.R.data());
  for (int n = 0; n <= p; ++n)
    for (int m = 0; m <= n; ++m) {
      cplx acc(0.0, 0.0);
      for (int k = 0; k <= n; ++k)
        for (int l = std::max(-k, m - (n - k)); l <= std::min(k, m + (n - k)); ++l)
          acc += mul(std::conj(coeff(R, k, l)), coeff(M_child, n - k, m - l));
      M_parent[tri(n, m)] += acc;
    }
}

void split_multipole(const cplx* M, int p, double* re, double* im) {
  for (int n = 0; n <= p; ++n)
    for (int m = -n; m <= n; ++m) {
      const cplx v = coeff(M, n, m);
      re[n * n + n + m] = v.real();
      im[n * n + n + m] = v.imag();
    }
}

void m2l(const double* M_re, const double* M_im, const Vec3& d, int p, cplx* L, OperatorScratch& s) {
  irregular_harmonics(d, p, s.I.data());
  split_multipole(s.I.data(), p, s.Ire.data(), s.Iim.data());
  for (int j = 0; j <= p; ++j)
    for (int t = 0; t <= j; ++t) {
      double re = 0.0, im = 0.0;
      for (int n = 0; n <= p - j; ++n) {
        const double* mr = M_re + n * n + n;
        const double* mi = M_im + n * n + n;
        const int o = (n + j) * (n + j) + (n + j) - t;
        const double* ir = &s.Ire[o];
        const double* ii = &s.Iim[o];
#pragma omp simd reduction(+ : re, im)
        for (int m = -n; m <= n; ++m) {
          re += mr[m] * ir[m] - mi[m] * ii[m];
          im += mr[m] * ii[m] + mi[m] * ir[m];
        }
      }
      const double sign = ((j + t) & 1) ? -1.0 : 1.0;
      L[tri(j, t)] += cplx(sign * re, sign * im);
    }
}

void l2l(const cplx* L_parent, const Vec3& shift, int p, cplx* L_child, OperatorScratch& s) {
  const cplx* R = s.R.data();
  regular_harmonics(shift, p, s.R.data());
  for (int j = 0; j <= p; ++j)
    for (int t = 0; t <= j; ++t) {
      cplx acc(0.0, 0.0);
      for (int k = 0; k <= p - j; ++k)
        for (int l = -k; l <= k; ++l) acc += mul(coeff(R, k, l), coeff(L_parent, j + k, t + l));
      L_child[tri(j, t)] += acc;
    }
}

double l2p(const cplx* L, const Vec3& x, int p, Vec3* field, OperatorScratch& s) {
  const cplx* R = s.R.data();
  regular_harmonics(x, p, s.R.data());
  double pot = 0.0;
  for (int n = 0; n <= p; ++n) {
    pot += mul(L[tri(n, 0)], R[tri(n, 0)]).real();
    for (int m = 1; m <= n; ++m) pot += 2.0 * mul(L[tri(n, m)], R[tri(n, m)]).real();
  }
  if (field) {
    // Degree-1 coefficients of the local expansion shifted to the target.
    cplx l10(0.0, 0.0), l11(0.0, 0.0);
    for (int k = 0; k < p; ++k)
      for (int l = -k; l <= k; ++l) {
        const cplx r = coeff(R, k, l);
        l10 += mul(r, coeff(L, 1 + k, l));
        l11 += mul(r, coeff(L, 1 + k, 1 + l));
      }
    // grad phi = (-Re l11, Im l11, l10); E = -grad phi
    *field = Vec3{l11.real(), -l11.imag(), -l10.real()};
  }
  return pot;
}

}  // namespace agglo::es::fmm
