// AVX2 versions of the spectral solver's small dense kernels (gemv2, gemv2x2, gemv2t), bit for bit the two-lane reference
// kernels of dense_ops.hpp (see there).
#include "agglo/electrostatics/spectral/dense_ops.hpp"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(AGGLO_NO_AVX2)
#define AGGLO_DENSE_OPS_AVX2 1
#include <immintrin.h>
#endif

namespace agglo::es::sh::kern {

#if defined(AGGLO_DENSE_OPS_AVX2)
#pragma GCC push_options
#pragma GCC target("avx2")
namespace {

// Most columns of a call (the pivot tables and the translations of degree <= 1023).
constexpr int kDenseOpsMaxCols = 1024;

// x (pairs x_k = (x[2k], x[2k+1])) reordered for the four-lane sums: per four columns k..k+3 the
// pairs (x_k, x_k+2, x_k+1, x_k+3); cols rounded down to a multiple of four.
inline __attribute__((always_inline)) void dense_ops_reorder(const double* x, int cols, double* xr) {
  for (int k = 0; k + 4 <= cols; k += 4) {
    double* o = xr + 2 * k;
    const double* i = x + 2 * k;
    o[0] = i[0], o[1] = i[1], o[2] = i[4], o[3] = i[5];
    o[4] = i[2], o[5] = i[3], o[6] = i[6], o[7] = i[7];
  }
}

// One row's four partial sums (s0..s3 of gemv2_reference) as lanes: P = (s0, s2), Q = (s1, s3).
inline __attribute__((always_inline)) void dense_ops_step(const double* a, int k, const double* xr, __m256d& P,
                                                          __m256d& Q) {
  const __m256d av = _mm256_loadu_pd(a + k);
  const __m256d a02 = _mm256_movedup_pd(av);         // a_k, a_k, a_k+2, a_k+2
  const __m256d a13 = _mm256_permute_pd(av, 0b1111);  // a_k+1, a_k+1, a_k+3, a_k+3
  P = _mm256_add_pd(P, _mm256_mul_pd(a02, _mm256_load_pd(xr + 2 * k)));
  Q = _mm256_add_pd(Q, _mm256_mul_pd(a13, _mm256_load_pd(xr + 2 * k + 4)));
}

// The tail columns (into s0) and the sum (s0 + s1) + (s2 + s3) of gemv2_reference, stored to y[0], y[1].
inline __attribute__((always_inline)) void dense_ops_finish(const double* a, int k, int cols, const double* x,
                                                            __m256d P, __m256d Q, double* y) {
  __m128d s0 = _mm256_castpd256_pd128(P), s2 = _mm256_extractf128_pd(P, 1);
  const __m128d s1 = _mm256_castpd256_pd128(Q), s3 = _mm256_extractf128_pd(Q, 1);
  for (; k < cols; ++k) s0 = _mm_add_pd(s0, _mm_mul_pd(_mm_set1_pd(a[k]), _mm_loadu_pd(x + 2 * k)));
  _mm_storeu_pd(y, _mm_add_pd(_mm_add_pd(s0, s1), _mm_add_pd(s2, s3)));
}

__attribute__((noinline)) void gemv2_avx2(const double* A, int lda, int rows, int cols, const double* x, double* y) {
  alignas(32) double xr[2 * kDenseOpsMaxCols];
  dense_ops_reorder(x, cols, xr);
  const int k4 = cols & ~3;
  int r = 0;
  for (; r + 2 <= rows; r += 2) {  // two rows at a time: four independent sums
    const double *a = A + static_cast<long>(r) * lda, *b = a + lda;
    __m256d P = _mm256_setzero_pd(), Q = P, P2 = P, Q2 = P;
    for (int k = 0; k < k4; k += 4) {
      dense_ops_step(a, k, xr, P, Q);
      dense_ops_step(b, k, xr, P2, Q2);
    }
    dense_ops_finish(a, k4, cols, x, P, Q, y + 2 * r);
    dense_ops_finish(b, k4, cols, x, P2, Q2, y + 2 * r + 2);
  }
  for (; r < rows; ++r) {
    const double* a = A + static_cast<long>(r) * lda;
    __m256d P = _mm256_setzero_pd(), Q = P;
    for (int k = 0; k < k4; k += 4) dense_ops_step(a, k, xr, P, Q);
    dense_ops_finish(a, k4, cols, x, P, Q, y + 2 * r);
  }
}

__attribute__((noinline)) void gemv2x2_avx2(const double* A, int lda, int rows, int cols, const double* x,
                                            const double* x2, double* y, double* y2) {
  alignas(32) double xr[2 * kDenseOpsMaxCols], zr[2 * kDenseOpsMaxCols];
  dense_ops_reorder(x, cols, xr);
  dense_ops_reorder(x2, cols, zr);
  const int k4 = cols & ~3;
  for (int r = 0; r < rows; ++r) {
    const double* a = A + static_cast<long>(r) * lda;
    __m256d P = _mm256_setzero_pd(), Q = P, P2 = P, Q2 = P;
    for (int k = 0; k < k4; k += 4) {
      dense_ops_step(a, k, xr, P, Q);
      dense_ops_step(a, k, zr, P2, Q2);
    }
    dense_ops_finish(a, k4, cols, x, P, Q, y + 2 * r);
    dense_ops_finish(a, k4, cols, x2, P2, Q2, y2 + 2 * r);
  }
}

// Columns k, k+1 of row a against v_r = (v[2r], v[2r+1]) as one four-lane product (a_k, a_k, a_k+1, a_k+1) x
// (v_r, v_r), the two lanes of each column as gemv2t_reference multiplies them.
inline __attribute__((always_inline)) __m256d dense_ops_tstep(const double* a, __m256d vr) {
  const __m256d a01 = _mm256_castpd128_pd256(_mm_loadu_pd(a));
  return _mm256_mul_pd(_mm256_permute4x64_pd(a01, 0b01010000), vr);
}

__attribute__((noinline)) void gemv2t_avx2(const double* A, int lda, int rows, int cols, const double* v, double* y) {
  int k = 0;
  for (; k + 8 <= cols; k += 8) {  // eight columns in four registers, down all rows
    double* yk = y + 2 * k;
    __m256d Y0 = _mm256_loadu_pd(yk), Y1 = _mm256_loadu_pd(yk + 4), Y2 = _mm256_loadu_pd(yk + 8),
            Y3 = _mm256_loadu_pd(yk + 12);
    for (int r = 0; r < rows; ++r) {
      const double* a = A + static_cast<long>(r) * lda + k;
      const __m256d vr = _mm256_broadcast_pd(reinterpret_cast<const __m128d*>(v + 2 * r));
      Y0 = _mm256_add_pd(Y0, dense_ops_tstep(a, vr));
      Y1 = _mm256_add_pd(Y1, dense_ops_tstep(a + 2, vr));
      Y2 = _mm256_add_pd(Y2, dense_ops_tstep(a + 4, vr));
      Y3 = _mm256_add_pd(Y3, dense_ops_tstep(a + 6, vr));
    }
    _mm256_storeu_pd(yk, Y0), _mm256_storeu_pd(yk + 4, Y1), _mm256_storeu_pd(yk + 8, Y2);
    _mm256_storeu_pd(yk + 12, Y3);
  }
  for (; k + 2 <= cols; k += 2) {
    __m256d Y0 = _mm256_loadu_pd(y + 2 * k);
    for (int r = 0; r < rows; ++r)
      Y0 = _mm256_add_pd(Y0, dense_ops_tstep(A + static_cast<long>(r) * lda + k,
                                             _mm256_broadcast_pd(reinterpret_cast<const __m128d*>(v + 2 * r))));
    _mm256_storeu_pd(y + 2 * k, Y0);
  }
  if (k < cols) {
    __m128d Y0 = _mm_loadu_pd(y + 2 * k);
    for (int r = 0; r < rows; ++r)
      Y0 = _mm_add_pd(Y0, _mm_mul_pd(_mm_set1_pd(A[static_cast<long>(r) * lda + k]), _mm_loadu_pd(v + 2 * r)));
    _mm_storeu_pd(y + 2 * k, Y0);
  }
}

const bool dense_ops_avx2 = __builtin_cpu_supports("avx2");

}  // namespace
#pragma GCC pop_options
#endif

bool has_avx2_kernels() {
#if defined(AGGLO_DENSE_OPS_AVX2)
  return dense_ops_avx2;
#else
  return false;
#endif
}

void gemv2(const double* A, int lda, int rows, int cols, const double* x, double* y) {
#if defined(AGGLO_DENSE_OPS_AVX2)
  if (dense_ops_avx2 && cols <= kDenseOpsMaxCols) return gemv2_avx2(A, lda, rows, cols, x, y);
#endif
  gemv2_reference(A, lda, rows, cols, x, y);
}

void gemv2x2(const double* A, int lda, int rows, int cols, const double* x, const double* x2, double* y, double* y2) {
#if defined(AGGLO_DENSE_OPS_AVX2)
  if (dense_ops_avx2 && cols <= kDenseOpsMaxCols) return gemv2x2_avx2(A, lda, rows, cols, x, x2, y, y2);
#endif
  gemv2x2_reference(A, lda, rows, cols, x, x2, y, y2);
}

void gemv2t(const double* A, int lda, int rows, int cols, const double* v, double* y) {
#if defined(AGGLO_DENSE_OPS_AVX2)
  if (dense_ops_avx2) return gemv2t_avx2(A, lda, rows, cols, v, y);
#endif
  gemv2t_reference(A, lda, rows, cols, v, y);
}

}  // namespace agglo::es::sh::kern
