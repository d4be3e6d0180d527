#pragma once
// Spherical-harmonic (multipole) solver for dielectric spheres, docs/model.md §B.2 item 3
// (Lindgren et al. 2018 J. Comput. Phys. 371, 712; reaction form of BSL's equation).
//
// Each sphere's surface charge is expanded in real spherical harmonics up to degree L
// (spectral/harmonics.hpp). With the regular expansion alpha of the potential of all other
// spheres plus the applied field about x_i, the exterior multipoles obey
//   B_lm = -gamma_l a^(2l+1) A_lm,   gamma_l = (kappa_i - kappa_0) l / ((kappa_i + kappa_0) l + kappa_0),
//   B_00 = q_i / (4 pi eps0 kappa_0)  (net charge q_i / kappa_0 exactly).
// Multipole-to-local translations between spheres are rotation based (rotate the pair axis to z,
// axial translation, rotate back): O(L^3) per pair and matrix-vector product; each pair uses its
// own truncation degree and frame order (at 1e-3 x target accuracy). The system
// is solved by restarted GMRES to min(tolerance, 1e-2 target_accuracy), warm-started from the
// previous solve (same number of spheres). Forces and torques use closed forms:
//   F_i = -kappa_0 4 pi eps0 sum_lm w_m beta_lm (a grad phi_ext)_lm,
//   M_i = -kappa_0 4 pi eps0 a sum_lm w_m beta_lm ((r x grad) phi_ext)_lm,   w_0 = 1, w_m = 1/2,
// energy U = 1/2 sum_i q_i (q_i/(4 pi eps0 kappa_0 a_i) + phi_ext,i(x_i))  (= 1/2 \int phi sigma_f dS,
// self energy of each shell included; applied potential -E.x, zero at the origin).
// L: SolverOptions::max_degree if > 0, else the smallest L with 2 (rho_a rho_b)^L <= target_accuracy
// over all pairs (spectral/degree.hpp), capped at max_degree_limit.
// Errors: invalid input (validate_spheres.hpp) throws InvalidSpheres, GMRES not converging
// agglo::NumericalError.
#include <memory>
#include <vector>

#include "agglo/electrostatics/registry.hpp"
#include "agglo/electrostatics/spectral/far_field.hpp"

namespace agglo::es {
// The default solver (solver.hpp).
inline constexpr std::string_view kSpectralSolver = kDefaultSolver;

std::unique_ptr<Solver> make_spectral_solver(const SolverOptions& opt);
// With `far` replacing the far field's options (the twins of tests and benchmarks; opt.far_field = "fmm").
std::unique_ptr<Solver> make_spectral_solver(const SolverOptions& opt, const sh::FarFieldOptions& far);

// far_field = "fmm" (far_field.hpp): the product is accurate to kFarFieldAccuracy x target_accuracy
// (relative 2-norm against the dense twin). Tighter is not meaningful: the dense product's own pair
// truncation (pair degrees at 1e-3 x target) differs from a product at higher pair degrees by ~5e-6 at
// the default target on the clusters of the tests.
inline constexpr double kFarFieldAccuracy = 0.1;
// far_field = "fmm": near pairs of at least this degree rotate through the shared quarter turns
// (pivot_rotation.hpp) instead of their own stored blocks (FrameRotation), unless
// FarFieldOptions::stored_rotations (the twin). Below it a pair's blocks are small (under 0.1 MB).
inline constexpr int kPivotDegree = 20;
double far_field_tolerance(const SolverOptions& opt);

// The twin checks of the far field: the degree L solve() chooses for p, and the sphere-sphere part of
// the product, alpha = M beta (scaled coefficients, ncoef(L) per sphere, layout of spectral_solver.cpp:
// beta_lm = B_lm / a^(l+1), alpha_lm = a^l A_lm), with opt.far_field; `far` replaces the far field's
// options (the negative controls of the tests); the product is applied `repeat` times after one set-up
// (the cost of one product, bench/bench_spectral_far_field.cpp).
int spectral_degree(const SolverOptions& opt, const Problem& p);
std::vector<double> spectral_product(const SolverOptions& opt, const Problem& p, const std::vector<double>& beta,
                                     const sh::FarFieldOptions* far = nullptr, int repeat = 1);

// Its entry in the solver registry (registry.hpp), with its cost model.
SolverType spectral_solver_type();
}  // namespace agglo::es
