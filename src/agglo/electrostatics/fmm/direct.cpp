#include "agglo/electrostatics/fmm/direct.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "agglo/core/cancel.hpp"

namespace agglo::es::fmm {

Points::Points(std::span<const Vec3> p) : x(p.size()), y(p.size()), z(p.size()) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    x[i] = p[i].x;
    y[i] = p[i].y;
    z[i] = p[i].z;
  }
}

void direct_sum(std::span<const Vec3> targets, std::span<const Vec3> sources,
                std::span<const double> charges, std::vector<double>* potential,
                std::vector<Vec3>* field) {
  const Points t(targets), s(sources);
  const std::size_t nt = t.size();
  std::vector<double> phi(nt, 0.0), ex(nt, 0.0), ey(nt, 0.0), ez(nt, 0.0);
  constexpr std::size_t block = 64;
  const std::size_t nblocks = (nt + block - 1) / block;
  const CancelToken* cancel = current_cancel_token();  // OpenMP threads have none of their own
#pragma omp parallel for schedule(dynamic, 4)
  for (std::size_t b = 0; b < nblocks; ++b) {
    if (cancel && cancel->cancelled()) continue;  // cancelled: skip the rest, thrown below
    const std::size_t i0 = b * block, n = std::min(block, nt - i0);
    p2p_accumulate(&t.x[i0], &t.y[i0], &t.z[i0], n, s.x.data(), s.y.data(), s.z.data(),
                   charges.data(), s.size(), &phi[i0], field ? &ex[i0] : nullptr, &ey[i0], &ez[i0]);
  }
  poll_cancel();
  if (potential) *potential = std::move(phi);
  if (field) {
    field->resize(nt);
    for (std::size_t i = 0; i < nt; ++i) (*field)[i] = {ex[i], ey[i], ez[i]};
  }
}

void direct_normal_field(const Points& pts, const Points& normals, std::span<const double> q,
                         std::span<double> y) {
  const std::size_t n = pts.size();
  const double *X = pts.x.data(), *Y = pts.y.data(), *Z = pts.z.data();
  const double *NX = normals.x.data(), *NY = normals.y.data(), *NZ = normals.z.data();
  const double* Q = q.data();
  // Every row is summed whole, over j in a fixed order, by one thread: the result does not depend on the
  // thread count or the schedule (a symmetric evaluation with per-thread accumulators, half the
  // arithmetic, gave last-bit differences between runs on more than one thread). j = i gives r = 0: skipped.
  const CancelToken* cancel = current_cancel_token();  // OpenMP threads have none of their own
#pragma omp parallel for schedule(dynamic, 16)
  for (std::size_t i = 0; i < n; ++i) {
    if (cancel && cancel->cancelled()) continue;  // cancelled: skip the rest, thrown below
    const double xi = X[i], yi = Y[i], zi = Z[i], nxi = NX[i], nyi = NY[i], nzi = NZ[i];
    double acc = 0.0;
#pragma omp simd reduction(+ : acc)
    for (std::size_t j = 0; j < n; ++j) {
      const double dx = xi - X[j], dy = yi - Y[j], dz = zi - Z[j];
      const double r2 = dx * dx + dy * dy + dz * dz;
      const double inv = r2 > 0.0 ? 1.0 / std::sqrt(r2) : 0.0;
      const double inv3 = inv * inv * inv;
      acc += Q[j] * (dx * nxi + dy * nyi + dz * nzi) * inv3;
    }
    y[i] = acc;
  }
  poll_cancel();
}

}  // namespace agglo::es::fmm
