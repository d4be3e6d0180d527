#include "agglo/dem/kick_drift.hpp"

#include "agglo/dem/contact/lanes.hpp"

// Every function here is inlined into the two below, so passing Lanes by value has no ABI to keep.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace agglo::dem {
namespace {

using Lane = contact::lanes::Quad;                              // four doubles
using Mask = std::int64_t __attribute__((vector_size(32)));  // a comparison of two Lanes

// Four consecutive Vec3s as three lanes: x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3.
struct Four {
  Lane a, b, c;
};
static_assert(sizeof(Four) == 4 * sizeof(Vec3));

[[gnu::always_inline]] inline Lane load4(const double* s) {
  Lane r;
  __builtin_memcpy(&r, s, sizeof r);
  return r;
}
[[gnu::always_inline]] inline void store4(double* d, Lane r) { __builtin_memcpy(d, &r, sizeof r); }
[[gnu::always_inline]] inline Four load4(const Vec3* p) {
  const double* d = &p->x;
  return {load4(d), load4(d + 4), load4(d + 8)};
}
[[gnu::always_inline]] inline void store4(Vec3* p, const Four& r) {
  double* d = &p->x;
  store4(d, r.a);
  store4(d + 4, r.b);
  store4(d + 8, r.c);
}
// Four particles' scalars laid over their components: s0 s0 s0 s1 | s1 s1 s2 s2 | s2 s3 s3 s3.
[[gnu::always_inline]] inline Four spread(Lane s) {
  return {__builtin_shufflevector(s, s, 0, 0, 0, 1), __builtin_shufflevector(s, s, 1, 1, 2, 2),
          __builtin_shufflevector(s, s, 2, 3, 3, 3)};
}
// One Vec3 repeated for four particles.
[[gnu::always_inline]] inline Four spread(const Vec3& u) {
  return {Lane{u.x, u.y, u.z, u.x}, Lane{u.y, u.z, u.x, u.y}, Lane{u.z, u.x, u.y, u.z}};
}
[[gnu::always_inline]] inline Four operator+(const Four& p, const Four& q) { return {p.a + q.a, p.b + q.b, p.c + q.c}; }
[[gnu::always_inline]] inline Four operator-(const Four& p, const Four& q) { return {p.a - q.a, p.b - q.b, p.c - q.c}; }
[[gnu::always_inline]] inline Four operator*(const Four& p, const Four& q) { return {p.a * q.a, p.b * q.b, p.c * q.c}; }

// |d|^2 of four particles, (dx dx + dy dy) + dz dz as Vec3's norm2.
[[gnu::always_inline]] inline Lane norm2(const Four& d) {
  const Four s = d * d;
  const Lane sx = __builtin_shufflevector(__builtin_shufflevector(s.a, s.b, 0, 3, 6, 7), s.c, 0, 1, 2, 5);
  const Lane sy = __builtin_shufflevector(__builtin_shufflevector(s.a, s.b, 1, 4, 7, 7), s.c, 0, 1, 2, 6);
  const Lane sz = __builtin_shufflevector(__builtin_shufflevector(s.a, s.b, 2, 5, 5, 5), s.c, 0, 1, 4, 7);
  return (sx + sy) + sz;
}

template <bool kGas>
[[gnu::always_inline]] inline void kick_four(const VerletArrays& a, std::size_t q) {
  Four v = load4(a.v + q);
  if constexpr (kGas) {
    const Four u = spread(a.u);
    v = (u + (v - u) * spread(load4(a.decay + q))) + load4(a.f + q) * spread(load4(a.lag + q) / load4(a.m + q));
  } else {
    v = v + load4(a.f + q) * spread(load4(a.kick_v + q));
  }
  store4(a.v + q, v);
  store4(a.w + q, load4(a.w + q) + load4(a.t + q) * spread(load4(a.kick_w + q)));
}

// Kick and drift of particles q..q+3; whether one of them moved beyond the limit (kTest).
template <bool kGas, bool kTest>
[[gnu::always_inline]] inline bool kick_drift_four(const VerletArrays& a, std::size_t q) {
  kick_four<kGas>(a, q);
  const Four x = load4(a.x + q) + load4(a.v + q) * spread(Lane{a.dt, a.dt, a.dt, a.dt});
  store4(a.x + q, x);
  if constexpr (!kTest) return false;
  const Mask far = norm2(x - load4(a.x_at_build + q)) > a.lim2;
  return (far[0] | far[1] | far[2] | far[3]) != 0;
}

template <bool kTest>
[[gnu::always_inline]] inline bool kick_drift_one(const VerletArrays& a, std::size_t q) {
  kick_one(a, q);
  a.x[q] += a.dt * a.v[q];
  return kTest && agglo::norm2(a.x[q] - a.x_at_build[q]) > a.lim2;
}

template <bool kGas, bool kTest>
[[gnu::always_inline]] inline bool kick_drift_range(const VerletArrays& a, std::size_t begin, std::size_t end) {
  bool far = false;
  std::size_t q = begin;
  for (; q + 4 <= end; q += 4) far = kick_drift_four<kGas, kTest>(a, q) || far;
  for (; q < end; ++q) far = kick_drift_one<kTest>(a, q) || far;
  return far;
}

template <bool kGas>
[[gnu::always_inline]] inline void kick_range(const VerletArrays& a, std::size_t begin, std::size_t end) {
  std::size_t q = begin;
  for (; q + 4 <= end; q += 4) kick_four<kGas>(a, q);
  for (; q < end; ++q) kick_one(a, q);
}

}  // namespace

// (a copy of the arrays' pointers, which the stores through them cannot change: no reload per iteration)
AGGLO_WIDE_CLONES bool kick_drift(const VerletArrays& arrays, std::size_t begin, std::size_t end) {
  const VerletArrays a = arrays;
  if (a.decay)
    return a.x_at_build ? kick_drift_range<true, true>(a, begin, end) : kick_drift_range<true, false>(a, begin, end);
  return a.x_at_build ? kick_drift_range<false, true>(a, begin, end) : kick_drift_range<false, false>(a, begin, end);
}

AGGLO_WIDE_CLONES void kick(const VerletArrays& arrays, std::size_t begin, std::size_t end) {
  const VerletArrays a = arrays;
  if (a.decay)
    kick_range<true>(a, begin, end);
  else
    kick_range<false>(a, begin, end);
}

}  // namespace agglo::dem

#pragma GCC diagnostic pop
