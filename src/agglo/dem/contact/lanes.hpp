#pragma once
// Several pairs at once in the fast pair loop (pair_kernel.hpp; docs/benchmarks_dem.md §9): T is either
// one double or a Lane of kLanes doubles (a GCC vector type). Every operation below is the IEEE operation
// of the scalar expression, lane by lane, and the pair loop's clones are built for "avx2" without "fma",
// so nothing is contracted: a lane gives the bits of the same expression evaluated on one double.
// Branches become selects (both sides computed, the same value kept).
#include <cmath>
#include <cstdint>

// Functions running lanes are also compiled for AVX2 (without FMA, so the same bits), chosen at load time.
// (-DAGGLO_LANE_CLONES= builds the baseline code only, to check that it gives the same bits.)
#ifndef AGGLO_LANE_CLONES
#if defined(__x86_64__) && !defined(__AVX2__) && !defined(__clang__)  // (clang: no clones of flatten functions)
#define AGGLO_LANE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define AGGLO_LANE_CLONES
#endif
#endif

// Every function here is inlined, so passing Lanes by value has no ABI to keep (GCC warns for 32-byte vectors).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace agglo::dem::contact::lanes {

inline constexpr int kLanes = 4;
using Lane = double __attribute__((vector_size(8 * kLanes)));
using Mask = std::int64_t __attribute__((vector_size(8 * kLanes)));  // what a comparison of Lanes gives

// A 3-vector of T with the component operations of core/vec3.hpp in the same order.
template <class T>
struct V3 {
  T x, y, z;
};

template <class T>
[[gnu::always_inline]] inline V3<T> operator+(const V3<T>& a, const V3<T>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
[[gnu::always_inline]] inline V3<T> operator-(const V3<T>& a, const V3<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
[[gnu::always_inline]] inline V3<T> operator-(const V3<T>& a) {
  return {-a.x, -a.y, -a.z};
}
// s * a and a * s: each component times s (Vec3's operator*= order).
template <class T>
[[gnu::always_inline]] inline V3<T> operator*(const T& s, const V3<T>& a) {
  return {a.x * s, a.y * s, a.z * s};
}
template <class T>
[[gnu::always_inline]] inline V3<T> operator*(const V3<T>& a, const T& s) {
  return {a.x * s, a.y * s, a.z * s};
}
template <class T>
[[gnu::always_inline]] inline V3<T> operator/(const V3<T>& a, const T& s) {
  return {a.x / s, a.y / s, a.z / s};
}
template <class T>
[[gnu::always_inline]] inline T dot(const V3<T>& a, const V3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
[[gnu::always_inline]] inline V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
[[gnu::always_inline]] inline T norm2(const V3<T>& a) {
  return dot(a, a);
}

[[gnu::always_inline]] inline double sqrt(double a) { return std::sqrt(a); }
// (a loop the compiler turns into one vector square root; -fno-math-errno, set for the whole project)
[[gnu::always_inline]] inline Lane sqrt(Lane a) {
  Lane r;
  for (int l = 0; l < kLanes; ++l) r[l] = __builtin_sqrt(a[l]);
  return r;
}
[[gnu::always_inline]] inline double abs(double a) { return std::abs(a); }
[[gnu::always_inline]] inline Lane abs(Lane a) {  // the sign bit cleared, as fabs
  return reinterpret_cast<Lane>(reinterpret_cast<Mask>(a) & INT64_MAX);
}
[[gnu::always_inline]] inline double copysign(double a, double b) { return std::copysign(a, b); }
[[gnu::always_inline]] inline Lane copysign(Lane a, Lane b) {  // |a| with the sign bit of b, as copysign
  return reinterpret_cast<Lane>((reinterpret_cast<Mask>(a) & INT64_MAX) | (reinterpret_cast<Mask>(b) & INT64_MIN));
}
template <class T>
[[gnu::always_inline]] inline T norm(const V3<T>& a) {
  return sqrt(dot(a, a));
}

// m ? a : b per lane.
[[gnu::always_inline]] inline double select(bool m, double a, double b) { return m ? a : b; }
[[gnu::always_inline]] inline Lane select(Mask m, Lane a, Lane b) { return m ? a : b; }
template <class M, class T>
[[gnu::always_inline]] inline V3<T> select(M m, const V3<T>& a, const V3<T>& b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
// std::min(a, b): (b < a) ? b : a.
template <class T>
[[gnu::always_inline]] inline T minimum(T a, T b) {
  return select(b < a, b, a);
}

// std::max(a, b): (a < b) ? b : a.
template <class T>
[[gnu::always_inline]] inline T maximum(T a, T b) {
  return select(a < b, b, a);
}

// T from a[0] (a Lane: a[0 .. kLanes)), and back.
template <class T>
[[gnu::always_inline]] inline T load(const double* a) {
  if constexpr (sizeof(T) == sizeof(double)) {
    return *a;
  } else {
    T v;
    __builtin_memcpy(&v, a, sizeof v);
    return v;
  }
}
template <class T>
[[gnu::always_inline]] inline void store(double* a, const T& v) {
  __builtin_memcpy(a, &v, sizeof v);
}

}  // namespace agglo::dem::contact::lanes

#pragma GCC diagnostic pop
