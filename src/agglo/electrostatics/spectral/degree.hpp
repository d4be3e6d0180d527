#pragma once
// Choice of the expansion degree L for the spectral solver (docs/model.md §B.2 item 3, B.4).
//
// For spheres of radii a (centre 0) and b (centre t on the axis) the image charges of the pair
// accumulate at the two limit points of the coaxal system, x1 x2 = a^2, (t-x1)(t-x2) = b^2.
// The expansion on sphere a converges like rho_a^l with rho_a = a / x_+ (x_+ the limit point
// inside sphere b), likewise rho_b. Induced coefficients of degree l on one sphere are seen by
// the other with a second factor of the same kind, so the pair's force error after truncation at
// degree L behaves like C q^L with q = max(rho_a, rho_b)^2 (equal spheres: (rho_a rho_b)^L; a
// point-like charge next to a large sphere: (a/t)^(2L)). The prefactor, fitted to the two-sphere
// reference (kappa 2.5..15, gaps 0.003..1 of the smaller radius, equal and unequal radii), is
// C = clamp(80 h / min(a, b), 1, 8), h the surface gap: the estimate is within a factor ~10
// above the measured force error and was never below it in that set.
namespace agglo::es::sh {

struct PairRatio {
  double rho_a = 0.0, rho_b = 0.0;  // convergence ratios seen from sphere a and sphere b
  double C = 8.0;                   // error prefactor
};

// t > a + b required.
PairRatio limit_ratios(double a, double b, double t);

// Per-degree decay rate q = max(rho_a, rho_b)^2.
double rate(const PairRatio& r);

// Smallest L >= 1 with C q^L <= tol.
int degree_for(const PairRatio& r, double tol);

// Estimated relative error C q^L.
double error_estimate(const PairRatio& r, int L);

}  // namespace agglo::es::sh
