#pragma once
// Axial multipole-to-local translation (basis of harmonics.hpp), docs/model.md §B.2 item 3.
//
// A source expansion phi = sum_nm B_nm I_n^m(x - c) about c = +t z (t > 0) has the local
// expansion phi = sum_jm A_jm R_j^m(x) about the origin with (same m, |m| <= j, n)
//   A_jm = sum_n (-1)^(m+n) F(m,j,n) B_nm / t^(j+n+1),  F = (j+n)! / sqrt((j-m)!(j+m)!(n-m)!(n+m)!).
// For c = -t z an extra (-1)^(j+n). In scaled variables (beta_n = B_n / b^(n+1) for a source
// sphere of radius b, alpha_j = a^j A_j for a target sphere of radius a):
//   alpha_jm = sum_n (-1)^(m+n) F(m,j,n) u^j v^(n+1) beta_nm,  u = a/t, v = b/t.
// Cost per translation: sum_m (L-|m|+1)^2 ~ 2 L^3 / 3.
#include <vector>

namespace agglo::es::sh {

class AxialTranslation {
 public:
  // Precompute the signed factors up to degree L (static: depends on L only).
  void prepare(int L);
  int degree() const { return L_; }
  // out (+)= translated coefficients; degrees <= Lmax (<= degree()) used for source and target.
  // sign = +1: source centre at +t z; -1: at -t z. `accumulate` adds into out.
  // Only frame orders |m| <= Mmax are translated.
  void apply(int Lmax, int Mmax, double u, double v, int sign, const double* in, double* out) const;
  // Both directions of a pair in one pass over the factors: out_a += apply(u, v, +1, in_b) and
  // out_b += apply(v, u, -1, in_a), each the same bits as the two apply calls. `powers` (optional): the
  // source scalings v^(m+1), u^(m+1) of source_powers for orders m <= min(Lmax, Mmax), else computed here
  // (std::pow, both ways: the same numbers).
  // With add = false the orders |m| <= min(Lmax, Mmax) of out_a, out_b are written instead (the same numbers
  // as adding to +0, but for the sign of a zero), the others left as they are.
  void apply_pair(int Lmax, int Mmax, double u, double v, const double* in_b, const double* in_a, double* out_a,
                  double* out_b, const double* powers = nullptr, bool add = true) const;
  // powers[2m] = v^(m+1), powers[2m+1] = u^(m+1) (std::pow), m = 0..Mmax: apply_pair's per-order
  // source scalings, kept by a caller that translates the same pair many times.
  static void source_powers(int Mmax, double u, double v, std::vector<double>& powers);
  // Smallest order M such that every m-block with m > M has operator-norm bound
  // (block size x largest entry, both directions) below tol: orders above M can be dropped.
  // Near contact the pair coupling is concentrated at small |m| around the pair axis.
  int order_cutoff(int Lmax, double u, double v, double tol) const;

 private:
  int L_ = -1;
  std::vector<double> f_;    // per m: (L-m+1)^2 row-major (rows j, cols n), signed
  std::vector<int> off_;
};

}  // namespace agglo::es::sh
