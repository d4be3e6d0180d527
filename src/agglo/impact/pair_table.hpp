#pragma once
// Isolated-pair electrostatics tabulated against the surface gap, for the "pair-corrected hold" of
// the DEM coupling (docs/electrostatics.md, "Coupling to the DEM").
//
// For two spheres (radii r_i, r_j, permittivities k_i, k_j in a medium k_0) the force on j along the
// line of centres and the energy are quadratic forms in the free charges:
//   F_ij(h) = q_i^2 A(h) + q_i q_j B(h) + q_j^2 C(h)      (> 0: repulsion)
//   U_ij(h) = q_i^2 a(h) + q_i q_j b(h) + q_j^2 c(h)
// A..c are computed once with the full solver at n log-spaced gaps h in [h_min, h_max] and
// interpolated with monotone cubic (Fritsch-Carlson) splines in log h. Beyond h_max the pair is
// treated as point charges (the polarisation correction there is O((r/d)^3) smaller).
#include <array>
#include <memory>
#include <vector>

#include "agglo/electrostatics/solver.hpp"

namespace agglo::impact {

struct PairKey {
  double ri, rj, ki, kj, k0;
  bool operator<(const PairKey& o) const;
};

class PairTable {
 public:
  PairTable(const es::SolverOptions& opt, const PairKey& key, double h_min, double h_max, int n);
  // Force on j (> 0 repulsive) [N] and pair energy [J] at surface gap h [m] (h > 0).
  void eval(double h, double qi, double qj, double& force, double& energy) const;
  double h_min() const { return h_.front(); }

 private:
  double coulomb_force(double h, double qi, double qj) const;
  PairKey key_;
  std::vector<double> s_;                 // log h
  std::vector<double> h_;
  std::array<std::vector<double>, 6> y_;  // A, B, C, a, b, c
  std::array<std::vector<double>, 6> m_;  // spline slopes d y / d s
};

// Process-wide cache: tables are built once per (radii, permittivities, medium), gap range and
// complete solver settings (every field of es::SolverOptions, compared through its operator<=>).
std::shared_ptr<const PairTable> pair_table(const es::SolverOptions& opt, const PairKey& key, double h_min,
                                            double h_max);

}  // namespace agglo::impact
