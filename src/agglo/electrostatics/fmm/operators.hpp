#pragma once
// The FMM operators, one function each (LaplaceFmm::evaluate in fmm.cpp only orchestrates them).
// Expansions of order p in the complex solid harmonics of solid_harmonics.hpp, stored for m >= 0
// (index tri(n, m)); negative orders follow from X_n^{-m} = (-1)^m conj(X_n^m).
//   multipole about c:  phi(x) = sum_{n<=p, |m|<=n} M_n^m I_n^m(x - c),  M_n^m = sum_k q_k conj(R_n^m(y_k - c))
//   local about c:      phi(x) = sum_{n<=p, |m|<=n} L_n^m R_n^m(x - c)
// Truncation errors (Q = sum |q_k|, sources within a of their centre):
//   P2M, evaluated at |x - c| = r > a:          |error| <= Q / (r - a) (a / r)^(p+1)
//   M2M and L2L re-centre without truncation (the degree <= p coefficients after the shift need
//     only degree <= p coefficients before it): exact up to rounding.
//   M2L keeps n + j <= p (n: multipole degree, j: local degree), i.e. the degree <= p part of the
//     expansion of 1/|D - w| in w = (y - c_S) - (x - c_T), |w| <= rho = a + r_T:
//     potential error <= Q / (D - rho) (rho / D)^(p+1),  field error <= Q sum_{k>p} (k+1) rho^(k-1) / D^(k+1).
// Each operator checks in tests/electrostatics/test_fmm_operators.cpp against direct sums.
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/electrostatics/fmm/direct.hpp"
#include "agglo/electrostatics/fmm/solid_harmonics.hpp"

namespace agglo::es::fmm {

// Per-thread scratch for the operators of order p (no allocation inside the operators).
struct OperatorScratch {
  explicit OperatorScratch(int p);
  std::vector<cplx> R, I;        // regular / irregular harmonics, tri_size(p)
  std::vector<double> Ire, Iim;  // irregular harmonics of all m, split, (p + 1)^2
};

// P2M: M += multipole about `center` of the points [begin, end) of `pts` with charges q[begin, end).
void p2m(const Points& pts, int begin, int end, const double* q, const Vec3& center, int p, cplx* M,
         OperatorScratch& s);

// M2M: M_parent += the child multipole M_child re-centred by `shift` = c_child - c_parent.
void m2m(const cplx* M_child, const Vec3& shift, int p, cplx* M_parent, OperatorScratch& s);

// The multipole of all orders m = -n..n, split into real and imaginary parts at n^2 + n + m
// (the layout m2l reads, (p + 1)^2 entries each).
void split_multipole(const cplx* M, int p, double* re, double* im);

// M2L: L += local expansion about c_T of the multipole (split form) about c_S, d = c_T - c_S.
void m2l(const double* M_re, const double* M_im, const Vec3& d, int p, cplx* L, OperatorScratch& s);

// L2L: L_child += the parent's local expansion L_parent re-centred by `shift` = c_child - c_parent.
void l2l(const cplx* L_parent, const Vec3& shift, int p, cplx* L_child, OperatorScratch& s);

// L2P: the potential of the local expansion L at offset x (target - centre); with `field` also
// E = -grad phi there (from the degree-0/1 coefficients of L shifted to the target).
double l2p(const cplx* L, const Vec3& x, int p, Vec3* field, OperatorScratch& s);

// P2P: direct sums from sources [s_begin, s_end) of S (charges q in S's order) onto targets
// [t_begin, t_end) of T, accumulated into phi and, when ex != nullptr, into ex, ey, ez (arrays in
// T's order); zero-distance pairs skipped.
inline void p2p(const Points& T, int t_begin, int t_end, const Points& S, int s_begin, int s_end,
                const double* q, double* phi, double* ex, double* ey, double* ez) {
  p2p_accumulate(&T.x[t_begin], &T.y[t_begin], &T.z[t_begin], t_end - t_begin, &S.x[s_begin], &S.y[s_begin],
                 &S.z[s_begin], &q[s_begin], s_end - s_begin, &phi[t_begin], ex ? &ex[t_begin] : nullptr,
                 ex ? &ey[t_begin] : nullptr, ex ? &ez[t_begin] : nullptr);
}

}  // namespace agglo::es::fmm
