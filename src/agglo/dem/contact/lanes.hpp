#pragma once
// Several pairs at once in the fast pair loop (pair_kernel.hpp; docs/benchmarks_dem.md §9, §12): T is either
// one double or a Lane of W doubles (a GCC vector type). Every operation below is the IEEE operation of the
// scalar expression, lane by lane, and nothing is contracted into an FMA (-ffp-contract=off for the whole
// build; the AVX2 clones are built without "fma"): a lane gives the bits of the same expression evaluated on
// one double. Branches become selects (both sides computed, the same value kept).
#include <cmath>
#include <cstdint>
#include <type_traits>

// Functions running lanes are also compiled for AVX2, chosen at load time.
// (-DAGGLO_LANE_CLONES= -DAGGLO_WIDE_LANES=0 builds the baseline code only, to check that it gives the same bits.)
#ifndef AGGLO_LANE_CLONES
#if defined(__x86_64__) && !defined(__AVX2__) && !defined(__clang__)  // (clang: no clones of flatten functions)
#define AGGLO_LANE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define AGGLO_LANE_CLONES
#endif
#endif
// The pair loop's wide form: eight pairs at a time, compiled for x86-64-v4 (AVX-512) and run where the CPU
// has it (wide_lanes()). (-DAGGLO_WIDE_LANES=0 leaves it out.)
#ifndef AGGLO_WIDE_LANES
#if defined(__x86_64__) && !defined(__clang__)
#define AGGLO_WIDE_LANES 1
#else
#define AGGLO_WIDE_LANES 0
#endif
#endif
#if AGGLO_WIDE_LANES
#define AGGLO_WIDE_TARGET __attribute__((target("arch=x86-64-v4")))
#else
#define AGGLO_WIDE_TARGET
#endif
// AGGLO_LANE_CLONES with an x86-64-v4 clone as well (the kick-drift loops, dem/kick_drift.cpp: the same four
// particles at a time, in AVX-512's encoding).
#if AGGLO_WIDE_LANES && !defined(__AVX2__)
#define AGGLO_WIDE_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define AGGLO_WIDE_CLONES AGGLO_LANE_CLONES
#endif

// Every function here is inlined, so passing Lanes by value has no ABI to keep (GCC warns for 32-byte vectors).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace agglo::dem::contact::lanes {

// W doubles as one GCC vector: the pair loop runs Lane<4>, and Lane<8> in its wide form (AGGLO_WIDE_TARGET).
// (GCC ignores a dependent vector_size on an alias template, hence one type per width)
template <int W>
struct LaneTypes;
template <>
struct LaneTypes<4> {
  using type = double __attribute__((vector_size(32)));
  using cells = std::int32_t __attribute__((vector_size(16)));
};
template <>
struct LaneTypes<8> {
  using type = double __attribute__((vector_size(64)));
  using cells = std::int32_t __attribute__((vector_size(32)));
};
template <int W>
using Lane = typename LaneTypes<W>::type;
template <int W>
using Cells = typename LaneTypes<W>::cells;  // W 32-bit integers (a table index per lane)
using Quad = Lane<4>;
// A Lane (not a double); kWidth<T> its doubles (a double: 1).
template <class T>
concept Vector = !std::is_arithmetic_v<T> && requires(T a) { a[0] + 1.0; };
template <class T>
inline constexpr int kWidth = static_cast<int>(sizeof(T) / sizeof(double));

// Whether the pair loop runs its wide form: built (AGGLO_WIDE_LANES) and the CPU has x86-64-v4, unless
// set_wide_lanes(false) was called (a test or benchmark comparing the two forms on one machine).
bool wide_lanes();
void set_wide_lanes(bool on);

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
template <Vector T>
[[gnu::always_inline]] inline T sqrt(T a) {
  T r;
  for (int l = 0; l < kWidth<T>; ++l) r[l] = __builtin_sqrt(a[l]);
  return r;
}
// The signed integers a comparison of two T gives.
template <Vector T>
using MaskOf = decltype(T{} < T{});
[[gnu::always_inline]] inline double abs(double a) { return std::abs(a); }
template <Vector T>
[[gnu::always_inline]] inline T abs(T a) {  // the sign bit cleared, as fabs
  return reinterpret_cast<T>(reinterpret_cast<MaskOf<T>>(a) & INT64_MAX);
}
[[gnu::always_inline]] inline double copysign(double a, double b) { return std::copysign(a, b); }
template <Vector T>
[[gnu::always_inline]] inline T copysign(T a, T b) {  // |a| with the sign bit of b, as copysign
  using M = MaskOf<T>;
  return reinterpret_cast<T>((reinterpret_cast<M>(a) & INT64_MAX) | (reinterpret_cast<M>(b) & INT64_MIN));
}
template <class T>
[[gnu::always_inline]] inline T norm(const V3<T>& a) {
  return sqrt(dot(a, a));
}

// m ? a : b per lane.
[[gnu::always_inline]] inline double select(bool m, double a, double b) { return m ? a : b; }
template <Vector T>
[[gnu::always_inline]] inline T select(MaskOf<T> m, T a, T b) {
  return m ? a : b;
}
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

// T from a[0] (a Lane: a[0 .. kWidth<T>)), and back.
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
