#pragma once
// Conversion between the spectral solver's real solid harmonics (harmonics.hpp: Schmidt-like,
// no Condon-Shortley phase) and the FMM's complex ones (fmm/solid_harmonics.hpp: Helgaker et al.
// sec. 9.13, with the phase), so that sphere expansions can enter the point FMM's operators.
// With s_nm = (-1)^m / sqrt((n-m)! (n+m)!) (from P_n^m = (-1)^m sqrt((n+m)!/(n-m)!) Pt_n^m):
//   r^n Pt_n^m e^{i m phi} = R_n^m(x) / s_nm,   Pt_n^m e^{i m phi} / r^(n+1) = s_nm I_n^m(x).
// Multipole phi = sum B_nm I_real_nm  ==  sum_{|m|<=n} M_n^m I_n^m  (M_n^{-m} = (-1)^m conj M_n^m) with
//   M_n^0 = s_n0 B_n0,   M_n^m = s_nm (B_nm - i B_n,-m) / 2   (m > 0).
// Local phi = sum_{|m|<=n} L_n^m R_n^m  ==  sum A_nm R_real_nm with
//   A_n0 = s_n0 L_n0,   A_nm = 2 s_nm Re L_n^m,   A_n,-m = -2 s_nm Im L_n^m   (m > 0).
// Lengths are in units of a scale ell (positions x / ell); for a sphere of radius a = rho ell the
// solver's scaled unknowns give B_nm / ell^(n+1) = rho^(n+1) beta_nm and alpha_nm = rho^n A_nm ell^n.
#include <vector>

#include "agglo/electrostatics/fmm/solid_harmonics.hpp"

namespace agglo::es::sh {

class ComplexBasis {
 public:
  explicit ComplexBasis(int p);
  int order() const { return p_; }
  // M (tri storage, fmm::tri_size(p)) = complex multipole of the real scaled multipole beta
  // (degrees <= min(p, L), beta has ncoef(L) entries) of a sphere of radius rho (in units of ell).
  void multipole_from_real(int L, double rho, const double* beta, fmm::cplx* M) const;
  // alpha (ncoef(L) entries) += real scaled local coefficients (degrees <= min(p, L)) of the complex
  // local expansion Lc about the centre of a sphere of radius rho (in units of ell).
  void add_real_local(int L, double rho, const fmm::cplx* Lc, double* alpha) const;

 private:
  int p_;
  std::vector<double> s_;  // s_nm at fmm::tri(n, m)
};

}  // namespace agglo::es::sh
