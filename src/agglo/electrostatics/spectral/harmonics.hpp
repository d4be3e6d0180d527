#pragma once
// Real solid harmonics used by the spectral solver (docs/model.md §B.2 item 3).
//
// Basis (Schmidt-like, no Condon-Shortley phase), for degree l and order -l <= m <= l:
//   Y_l^m(theta, phi) = Pt_l^|m|(cos theta) * { cos(m phi)  (m >= 0);  sin(|m| phi)  (m < 0) }
//   Pt_l^m = sqrt((l-m)!/(l+m)!) P_l^m,  P_l^m the associated Legendre function without (-1)^m.
// |Y_l^m| <= 1 everywhere and  \int Y_l^m Y_l'^m' dOmega = delta * 4 pi/(2l+1) * (m == 0 ? 1 : 1/2).
// Regular solid harmonic R_l^m(x) = r^l Y_l^m, irregular I_l^m(x) = Y_l^m / r^(l+1).
// Coefficients of degree <= L are stored in one array at index l*l + l + m (size (L+1)^2).
#include <cstddef>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::es::sh {

constexpr int idx(int l, int m) { return l * l + l + m; }
constexpr int ncoef(int L) { return (L + 1) * (L + 1); }

// Inner-product weight of Y_l^m over the unit sphere divided by 4 pi: (m == 0 ? 1 : 1/2)/(2l+1).
inline double norm_weight(int l, int m) { return (m == 0 ? 1.0 : 0.5) / (2 * l + 1); }

// All Y_l^m(direction of d) for l <= L (d need not be normalised; d != 0) into out[ncoef(L)].
void eval_surface(int L, const Vec3& d, double* out);
// Regular solid harmonics R_l^m(x) = r^l Y_l^m for l <= L.
void eval_regular(int L, const Vec3& x, double* out);
// Irregular solid harmonics I_l^m(x) = Y_l^m / r^(l+1) for l <= L (x != 0).
void eval_irregular(int L, const Vec3& x, double* out);

// Gradient of phi(x) = sum_lm a_lm R_l^m(x) (degree <= L): the coefficients (degree <= L-1,
// stored in arrays of size ncoef(L)) of d phi/dx, d phi/dy, d phi/dz in the same basis.
void gradient(int L, const double* a, double* gx, double* gy, double* gz);

// Rotation generator G = r x grad acting on f = sum_lm a_lm Y_l^m (degree-preserving): the
// coefficients of G_x f, G_y f, G_z f. (G f)(x) is d/dt f(Rot(axis, -t) x) at t = 0 ... i.e. the
// change of f under an infinitesimal rotation of the argument: G_z = d/dphi.
void rotation_generator(int L, const double* a, double* rx, double* ry, double* rz);

// Weighted inner product sum_lm norm_weight(l,m) a_lm b_lm = (1/4 pi) \int f g dOmega.
double dot(int L, const double* a, const double* b);

}  // namespace agglo::es::sh
