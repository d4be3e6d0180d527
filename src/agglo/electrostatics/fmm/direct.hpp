#pragma once
// Direct O(N^2) Laplace sums (the reference twin of the FMM), double precision, OpenMP.
//   phi_i = sum_j q_j / |t_i - s_j|,   E_i = sum_j q_j (t_i - s_j) / |t_i - s_j|^3
// Pairs at zero distance (a point with itself) are skipped. Units are the caller's
// (multiply by 1/(4 pi eps0) for SI potential [V] and field [V/m] from charges [C]).
#include <cmath>
#include <span>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::es::fmm {

// Structure-of-arrays point set (vectorisable inner loops).
struct Points {
  std::vector<double> x, y, z;
  Points() = default;
  explicit Points(std::span<const Vec3> p);
  std::size_t size() const { return x.size(); }
};

// Accumulate into phi/ex/ey/ez (any of them may be null only as a group: phi alone, or all four).
// Inner loop over sources, vectorised; zero-distance pairs contribute nothing.
inline void p2p_accumulate(const double* tx, const double* ty, const double* tz, std::size_t nt,
                           const double* sx, const double* sy, const double* sz, const double* q,
                           std::size_t ns, double* phi, double* ex, double* ey, double* ez) {
  for (std::size_t i = 0; i < nt; ++i) {
    const double xi = tx[i], yi = ty[i], zi = tz[i];
    double p = 0.0, fx = 0.0, fy = 0.0, fz = 0.0;
#pragma omp simd reduction(+ : p, fx, fy, fz)
    for (std::size_t j = 0; j < ns; ++j) {
      const double dx = xi - sx[j], dy = yi - sy[j], dz = zi - sz[j];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double inv = r2 > 0.0 ? 1.0 / std::sqrt(r2) : 0.0;
      const double qi = q[j] * inv;
      const double qi3 = qi * inv * inv;
      p += qi;
      fx += qi3 * dx;
      fy += qi3 * dy;
      fz += qi3 * dz;
    }
    phi[i] += p;
    if (ex) {
      ex[i] += fx;
      ey[i] += fy;
      ez[i] += fz;
    }
  }
}

// Potential and/or field at targets from charged sources (OpenMP over targets). Both sums stop early
// and throw InterruptedError when the calling thread's cancel token is set (core/cancel.hpp).
void direct_sum(std::span<const Vec3> targets, std::span<const Vec3> sources,
                std::span<const double> charges, std::vector<double>* potential,
                std::vector<Vec3>* field);

// Normal field at the source points themselves:  y_i = sum_{j != i} q_j (x_i - x_j) . n_i / |x_i - x_j|^3.
// The BEM matrix-vector product (direct mode). OpenMP over rows, each row summed in a fixed order: the
// result is bitwise the same at any thread count.
void direct_normal_field(const Points& pts, const Points& normals, std::span<const double> q,
                         std::span<double> y);

}  // namespace agglo::es::fmm
