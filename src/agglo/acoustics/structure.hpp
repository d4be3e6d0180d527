#pragma once
// Aggregate structure of a DSMC sample (docs/acoustics.md §1.8; issue 26). A population sets it with
// population.structure: "compact" (default: a particle is a sphere of its volume) or "fractal". A solid
// sample of a fractal population is an aggregate of n_p primaries of radius r_p [m] holding its solid
// volume, V_s = n_p (4/3) pi r_p^3 (n_p real-valued, n_p = V_s / v_p). Its radii [m]:
//   collision radius  R_c = max(r_v, r_p (n_p / k_f)^(1/D_f))   (fractal law: Forrest & Witten 1979;
//                                                               e.g. Sorensen 2011, eq. 1; D_f, k_f per population)
//   mobility radius   R_m = R_c                                 (mobility_radius = "collision", default)
//                     R_m = max(r_v, r_p n_p^0.46)              (mobility_radius = "sorensen": the continuum-regime
//                                                               fit of Sorensen 2011 for DLCA-like aggregates)
// D_f and k_f are those of the radius the user means by R_c (with the prefactor of the radius-of-gyration law
// R_c = R_g; docs/studies/flyash_outcomes.md fits them to the characteristic radius sqrt(5/3) R_g),
// with r_v = (3 (V_s + V_l) / (4 pi))^(1/3) the volume-equivalent radius: an aggregate whose law gives less
// than r_v (few primaries with k_f > 1, or a sample smaller than one primary) is a compact sphere. With
// D_f = 3, k_f = 1 both laws give r_v: the fractal path is then the compact one.
// What the DSMC does with them (samples.hpp): the kernels see d = 2 R_c as the particle diameter (collision
// cross-sections, wake and radiation-pressure sizes, the Brownian (d_i + d_j)); the drag sees d_m = 2 R_m:
//   C_c = C_c(d_m),  tau = m C_c / (3 pi mu_g d_m)  (Stokes drag 3 pi mu_g d_m v / C_c on the mass m),
//   Re = rho_g |u - v| d_m / mu_g,  Brownian diffusivity k_B T C_c / (3 pi mu_g d_m);
// for a compact sphere d = d_m = d_v and tau = rho d^2 C_c / (18 mu_g), as before. Outcomes (critical
// velocity, outcome tables), psd.csv, snapshots and the PM cuts by volume use the volume-equivalent diameter
// d_v = 2 r_v; the aerodynamic PM cut uses 18 mu_g tau = rho_0 d_a^2 C_c(d_a) (so the mobility diameter).
// Liquid and mixed samples, and the samples of compact populations, are compact spheres. Merging
// (merge.hpp) adds the primary counts; the primary radius is kept when both are equal, else it is the
// cube mean ((n_i r_i^3 + n_j r_j^3) / (n_i + n_j))^(1/3), so that count and volume are both conserved
// (droplets hold n_p = 0). A broken pair's fragments (fragments.hpp) get primaries in proportion to their
// mass and the pair's primary radius. The merged sample follows the law of its population (that of the
// partner of larger volume).
// Sorensen C. M. (2011), The mobility of fractal aggregates: a review, Aerosol Sci. Technol. 45, 765-779.
// Forrest S. R., Witten T. A. (1979), Long-range correlations in smoke-particle aggregates, J. Phys. A 12, L109.
#include <string_view>

namespace agglo::acoustics {

enum class MobilityRule { collision, sorensen };

// The structure of one population (compact: every other field unused).
struct StructureLaw {
  bool fractal = false;
  double primary_radius = 0.0;     // r_p [m]
  double fractal_dimension = 3.0;  // D_f
  double fractal_prefactor = 1.0;  // k_f
  bool from_table = false;         // D_f, k_f from the dry outcome table (population.fractal_law = "table")
  MobilityRule mobility = MobilityRule::collision;
};

// Exponent of the continuum mobility fit of Sorensen 2011: R_m = r_p n_p^0.46.
inline constexpr double kSorensenMobilityExponent = 0.46;

// R_c and R_m [m] of an aggregate of n primaries of radius rp [m] and volume-equivalent radius rv [m].
double collision_radius(const StructureLaw& law, double n, double rp, double rv);
double mobility_radius(const StructureLaw& law, double n, double rp, double rv);

// Primary count and radius of a merged pair (n_i primaries of radius r_i, n_j of r_j; the rule above).
struct Primaries {
  double count = 0.0, radius = 0.0;  // n_p, r_p [m]
};
Primaries merged_primaries(double ni, double ri, double nj, double rj);

}  // namespace agglo::acoustics
