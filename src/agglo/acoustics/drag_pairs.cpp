// The exact step of drag.hpp on several samples at once: two in SSE2 lanes, four in AVX2 lanes where
// the processor has them (chosen at run time). The step itself is drag_lanes.inc, written once for any
// lane width: the arithmetic of Motion::advance_exact, operation for operation and in the same order,
// so that every result is bit for bit the reference's (tests/acoustics/test_motion_pairs.cpp). No FMA
// is enabled (AVX2 alone), so no product and sum are contracted. Lanes that take one of the rare
// branches (wave-phase cache refill, C_I > 1.001, h / tau_e <= 0.01, Re outside the polynomial's range,
// a wrap) are finished by the scalar code of the reference for that sample.
#include <cmath>
#include <cstdint>

#include "agglo/acoustics/drag.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(AGGLO_NO_AVX2)
#define AGGLO_LANES_AVX2 1
#include <immintrin.h>
#endif

// Forced inline: the lane helpers are compiled inside the function of their instruction set.
#if defined(__GNUC__)
#define AGGLO_LANES inline __attribute__((always_inline))
#else
#define AGGLO_LANES inline
#endif

// The lane primitives named alike in SSE2 (P = _mm, B = 128) and AVX2 (P = _mm256, B = 256).
#define AGGLO_LANE_COMMON(P, B)                                                                           \
  AGGLO_LANES V set1(double a) { return P##_set1_pd(a); }                                                 \
  AGGLO_LANES V load(const std::vector<double>& a, std::size_t i) { return P##_loadu_pd(a.data() + i); }  \
  AGGLO_LANES V loada(const double* a) { return P##_loadu_pd(a); }                                        \
  AGGLO_LANES void store(std::vector<double>& a, std::size_t i, V v) { P##_storeu_pd(a.data() + i, v); }  \
  AGGLO_LANES V vand(V a, V b) { return P##_and_pd(a, b); }                                               \
  AGGLO_LANES V vor(V a, V b) { return P##_or_pd(a, b); }                                                 \
  AGGLO_LANES V neg(V a) { return P##_xor_pd(a, P##_set1_pd(-0.0)); } /* -a, as unary minus */            \
  AGGLO_LANES V absv(V a) { return P##_andnot_pd(P##_set1_pd(-0.0), a); }                                 \
  AGGLO_LANES V vsqrt(V a) { return P##_sqrt_pd(a); }                                                     \
  AGGLO_LANES V vmin(V a, V b) { return P##_min_pd(a, b); } /* b where a is NaN */                        \
  AGGLO_LANES int mask(V m) { return P##_movemask_pd(m); }                                                \
  AGGLO_LANES VI bits(V a) { return P##_castpd_si##B(a); }                                                \
  AGGLO_LANES V from_bits(VI a) { return P##_castsi##B##_pd(a); }                                         \
  AGGLO_LANES VI iset1(long long a) { return P##_set1_epi64x(a); }                                        \
  AGGLO_LANES VI iand(VI a, VI b) { return P##_and_si##B(a, b); }                                         \
  AGGLO_LANES VI ior(VI a, VI b) { return P##_or_si##B(a, b); }                                           \
  AGGLO_LANES VI iadd(VI a, VI b) { return P##_add_epi64(a, b); }                                         \
  AGGLO_LANES VI shr52(VI a) { return P##_srli_epi64(a, 52); }                                            \
  AGGLO_LANES VI shl52(VI a) { return P##_slli_epi64(a, 52); }

namespace agglo::acoustics {

#if defined(__SSE2__)
namespace {
namespace pair_lanes {  // (named: unity batches join the anonymous namespaces of several files)
using V = __m128d;  // + - * / on V are the IEEE operations of the scalar code, per lane
using VI = __m128i;  // 64-bit integer lanes (the bit tricks of detail_log and detail_exp_small)
constexpr int W = 2, kAll = 3;
AGGLO_LANE_COMMON(_mm, 128)
AGGLO_LANES double get(V v, int l) { return l == 0 ? _mm_cvtsd_f64(v) : _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)); }
AGGLO_LANES V put(V v, int l, double a) {
  return l == 0 ? _mm_move_sd(v, _mm_set_sd(a)) : _mm_unpacklo_pd(v, _mm_set_sd(a));
}
AGGLO_LANES V select(V mask, V a, V b) { return _mm_or_pd(_mm_and_pd(mask, a), _mm_andnot_pd(mask, b)); }
AGGLO_LANES V lt(V a, V b) { return _mm_cmplt_pd(a, b); }
AGGLO_LANES V le(V a, V b) { return _mm_cmple_pd(a, b); }
AGGLO_LANES V gt(V a, V b) { return _mm_cmpgt_pd(a, b); }
AGGLO_LANES V ge(V a, V b) { return _mm_cmpge_pd(a, b); }
#include "agglo/acoustics/drag_lanes.inc"
}  // namespace pair_lanes
}  // namespace
#endif

#if defined(AGGLO_LANES_AVX2)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace {
namespace quad_lanes {
using V = __m256d;
using VI = __m256i;
constexpr int W = 4, kAll = 15;
AGGLO_LANE_COMMON(_mm256, 256)
AGGLO_LANES double get(V v, int l) {
  alignas(32) double a[4];
  _mm256_store_pd(a, v);
  return a[l];
}
AGGLO_LANES V put(V v, int l, double x) {
  alignas(32) double a[4];
  _mm256_store_pd(a, v);
  a[l] = x;
  return _mm256_load_pd(a);
}
AGGLO_LANES V select(V mask, V a, V b) { return _mm256_blendv_pd(b, a, mask); }
AGGLO_LANES V lt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
AGGLO_LANES V le(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LE_OQ); }
AGGLO_LANES V gt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
AGGLO_LANES V ge(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GE_OQ); }
#include "agglo/acoustics/drag_lanes.inc"
// The four-lane step (compiled for AVX2; called only where the processor has it).
__attribute__((noinline)) std::size_t step_quads(const Motion& m, SampleSet& p, std::size_t begin,
                                                 std::size_t end, const Motion::StepTrig& tr, double h) {
  return step_lanes(m, p, begin, end, tr, h);
}
}  // namespace quad_lanes
}  // namespace
#pragma GCC pop_options
#endif

void Motion::advance_exact_pairs(SampleSet& p, std::size_t begin, std::size_t end, const StepTrig& tr,
                                 double h) const {
#if defined(__SSE2__)
  if (sound.u_amp > 0.0 && inertia_correction) {
    std::size_t i = begin;
#if defined(AGGLO_LANES_AVX2)
    static const bool avx2 = __builtin_cpu_supports("avx2");
    if (avx2 && max_lanes >= 4) i = quad_lanes::step_quads(*this, p, i, end, tr, h);
#endif
    i = pair_lanes::step_lanes(*this, p, i, end, tr, h);
    if (i < end) advance_exact(p, i, tr, h);
    return;
  }
#endif
  advance_exact_block(p, begin, end, tr, h);  // without sound or C_I (not the default), or without SSE2
}

}  // namespace agglo::acoustics

#undef AGGLO_LANES
#undef AGGLO_LANE_COMMON
#undef AGGLO_LANES_AVX2
