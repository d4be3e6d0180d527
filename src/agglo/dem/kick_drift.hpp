#pragma once
// The half kick and the drift of velocity Verlet (dem_system.hpp) over a range of particles, four at a
// time: the twelve doubles of four consecutive Vec3s as three GCC vector lanes, every component the IEEE
// operation of the one-particle form in the same order, so a range gives the bits of kick_one and the
// drift one particle at a time (tests/dem/test_kick_drift.cpp; docs/benchmarks_dem.md §10).
//   kick  (no gas):  v += (h/m) f,  w += (h/I) t,  h = dt/2
//   kick  (gas):     v = u + E (v - u) + (lag/m) f,  E = exp(-h/tau), lag = tau (1 - E)  (exact drag over h)
//   drift:           x += dt v
//   rebuild test:    |x - x_at_build|^2 > lim2  (NeighborList::moved_beyond)
#include <cstddef>

#include "agglo/core/vec3.hpp"

namespace agglo::dem {

// The arrays of a step (one entry per particle; DemSystem::verlet_arrays): pointers into the system's
// vectors, valid while none of them is resized (within a step; DemSystem takes them afresh each step).
struct VerletArrays {
  Vec3 *x = nullptr, *v = nullptr, *w = nullptr;
  const Vec3 *f = nullptr, *t = nullptr;
  const double *kick_v = nullptr, *kick_w = nullptr;  // h/m, h/I
  // Gas drag (null: none): E and lag per particle, the masses and the gas velocity u.
  const double *decay = nullptr, *lag = nullptr, *m = nullptr;
  Vec3 u;
  const Vec3* x_at_build = nullptr;  // null: no rebuild test
  double dt = 0.0, lim2 = 0.0;
};

// The half kick of particle q, one particle (the reference of the range forms).
[[gnu::always_inline]] inline void kick_one(const VerletArrays& a, std::size_t q) {
  if (a.decay)
    a.v[q] = a.u + a.decay[q] * (a.v[q] - a.u) + (a.lag[q] / a.m[q]) * a.f[q];
  else
    a.v[q] += a.kick_v[q] * a.f[q];
  a.w[q] += a.kick_w[q] * a.t[q];
}

// Kick, drift and rebuild test of particles [begin, end); true when one of them moved beyond the limit.
bool kick_drift(const VerletArrays& a, std::size_t begin, std::size_t end);
// The closing half kick of particles [begin, end).
void kick(const VerletArrays& a, std::size_t begin, std::size_t end);

}  // namespace agglo::dem
