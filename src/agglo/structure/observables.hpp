#pragma once
// Observables of an aggregate (docs/model.md §S.4):
//   point-mass R_g:  R_g,pm^2 = (1/N) sum_i |x_i - x_c|^2, x_c = (1/N) sum x_i (each primary weight 1;
//                    the R_g of the fractal law, structure/fractal.hpp) [m];
//   sphere R_g:      R_g,sph^2 = sum_i m_i (|x_i - x_m|^2 + (3/5) r_i^2) / sum m_i, m_i ~ r_i^3,
//                    x_m the centre of mass (the solid spheres' own 3/5 r^2 term included) [m];
//   contacts:        pairs with |d_ij - (r_i + r_j)| <= kContactTolerance min(r_i, r_j) (aggregate.hpp);
//                    coordination number = contacts per primary, and its distribution;
//   fractal fit:     least squares of ln(R_g,pm / abar) = (1/D_f) ln N - (1/D_f) ln k_f over an ensemble
//                    (ln N is exact and R_g scatters, so R_g is the dependent variable: regressing ln N on
//                    ln R_g would bias D_f low by the scatter), D_f = 1/slope, k_f = exp(-intercept D_f),
//                    with the standard error of D_f (that of the slope times D_f^2).
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "agglo/structure/aggregate.hpp"

namespace agglo::structure {

double rg_point_mass(const Aggregate& a);
double rg_spheres(const Aggregate& a);

struct Contacts {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // i < j
  std::vector<int> coordination;                           // per primary
  double max_error = 0.0;  // largest |d_ij - (r_i + r_j)| / min(r_i, r_j) over the contacts
};

// Contacts and the first overlap found (i, j, overlap / min radius); brute force O(N^2).
struct ContactScan {
  Contacts contacts;
  bool overlap = false;
  std::size_t oi = 0, oj = 0;
  double overlap_depth = 0.0;  // (r_i + r_j - d_ij) / min(r_i, r_j)
};
ContactScan scan_contacts(const Aggregate& a);

// counts[k] = primaries with k contacts, k = 0..max
std::vector<int> coordination_histogram(const std::vector<int>& coordination);

// Number of connected components of the contact graph.
std::size_t connected_components(std::size_t n, const std::vector<std::pair<std::size_t, std::size_t>>& pairs);

struct FractalFit {
  double fractal_dimension = 0.0;  // D_f (slope)
  double fractal_prefactor = 0.0;  // k_f = exp(intercept)
  double dimension_stderr = 0.0;   // standard error of the slope
  std::size_t points = 0;
};
// Fit over (N_k, R_g,k / abar_k); at least three aggregates of at least two sizes.
FractalFit fit_fractal(const std::vector<double>& n, const std::vector<double>& rg_over_a);

}  // namespace agglo::structure

namespace agglo::structure {

// Growth fit of one generated aggregate: fit_fractal over its index prefixes n = N, N/2, N/4, ... >= 16
// (the first n primaries; the builders append, so these are the intermediate clusters of BPCA, of BCCA
// and of the fractal builder when N is a power of two times the sub-cluster size). None below 3 prefixes.
std::optional<FractalFit> growth_fit(const Aggregate& a);

// Everything agglo aggregate reports about one structure.
struct Summary {
  std::size_t primaries = 0;
  double abar = 0.0;                // geometric-mean radius [m]
  double rg_point_mass = 0.0;       // [m]
  double rg_spheres = 0.0;          // [m]
  Contacts contacts;
  std::vector<int> coordination_counts;  // coordination_histogram
  double mean_coordination = 0.0;
  std::optional<FractalFit> growth;
};
Summary summarize(const Aggregate& a, const Contacts& contacts, bool growth_order);

}  // namespace agglo::structure
