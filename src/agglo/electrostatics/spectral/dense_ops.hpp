#pragma once
// Small dense kernels of the spectral solver, written with GCC/Clang vector extensions so that
// two right-hand sides are processed in one SIMD register (no reassociation of sums needed).
//   y = A x     for a row-major A (rows x cols) and two interleaved vectors x = (x1[k], x2[k]);
//   y += A^T v  likewise (interleaved v and y).
//   gemv2x2: two y = A x at once.
// gemv2, gemv2x2 and gemv2t (dense_ops.cpp) run four-lane AVX2 code where the processor has it (chosen at run
// time), the same products and sums in the same order as the two-lane reference kernels below
// (gemv2_reference, gemv2x2_reference; no FMA is enabled, so nothing is contracted): every result is the
// reference's bit for bit (tests/electrostatics/test_dense_ops.cpp). The AVX2 code takes the columns
// four at a time as the reference does (partial sums s0..s3 of columns k = 0, 1, 2, 3 mod 4), with the
// duplicated matrix entries (a_k, a_k, a_k+2, a_k+2) and (a_k+1, a_k+1, a_k+3, a_k+3) loaded by vmovddup
// against the vector pairs (x_k, x_k+2) and (x_k+1, x_k+3) reordered once per call: no shuffle in the
// inner loop, half the floating-point instructions of the two-lane code, and two rows (gemv2) or two
// vectors (gemv2x2) at a time for four independent sums. gemv2t's AVX2 code keeps eight columns of y
// (four registers of two columns x two vectors) in registers while it runs down the rows, each lane
// taking the same products in the same row order as gemv2t_reference: one pass over A, y loaded and
// stored once per eight columns instead of once per row.
namespace agglo::es::sh::kern {

typedef double v2d __attribute__((vector_size(16)));

// y[2r], y[2r+1] = sum_k A[r*lda + k] * (x[2k], x[2k+1]),  r < rows
inline void gemv2_reference(const double* A, int lda, int rows, int cols, const double* x, double* y) {
  const v2d* X = reinterpret_cast<const v2d*>(x);
  for (int r = 0; r < rows; ++r) {
    const double* a = A + static_cast<long>(r) * lda;
    v2d s0 = {0, 0}, s1 = {0, 0}, s2 = {0, 0}, s3 = {0, 0};
    int k = 0;
    for (; k + 4 <= cols; k += 4) {
      s0 += a[k] * X[k];
      s1 += a[k + 1] * X[k + 1];
      s2 += a[k + 2] * X[k + 2];
      s3 += a[k + 3] * X[k + 3];
    }
    for (; k < cols; ++k) s0 += a[k] * X[k];
    v2d s = (s0 + s1) + (s2 + s3);
    y[2 * r] = s[0];
    y[2 * r + 1] = s[1];
  }
}

// gemv2_reference for two pairs of vectors (x, y) and (x2, y2) sharing A: one pass over A, and each result the
// same bits as gemv2 gives it (the same four partial sums, added in the same order).
inline void gemv2x2_reference(const double* A, int lda, int rows, int cols, const double* x, const double* x2, double* y,
                    double* y2) {
  const v2d* X = reinterpret_cast<const v2d*>(x);
  const v2d* Z = reinterpret_cast<const v2d*>(x2);
  for (int r = 0; r < rows; ++r) {
    const double* a = A + static_cast<long>(r) * lda;
    v2d s0 = {0, 0}, s1 = {0, 0}, s2 = {0, 0}, s3 = {0, 0};
    v2d t0 = {0, 0}, t1 = {0, 0}, t2 = {0, 0}, t3 = {0, 0};
    int k = 0;
    for (; k + 4 <= cols; k += 4) {
      s0 += a[k] * X[k];
      t0 += a[k] * Z[k];
      s1 += a[k + 1] * X[k + 1];
      t1 += a[k + 1] * Z[k + 1];
      s2 += a[k + 2] * X[k + 2];
      t2 += a[k + 2] * Z[k + 2];
      s3 += a[k + 3] * X[k + 3];
      t3 += a[k + 3] * Z[k + 3];
    }
    for (; k < cols; ++k) {
      s0 += a[k] * X[k];
      t0 += a[k] * Z[k];
    }
    const v2d s = (s0 + s1) + (s2 + s3), t = (t0 + t1) + (t2 + t3);
    y[2 * r] = s[0];
    y[2 * r + 1] = s[1];
    y2[2 * r] = t[0];
    y2[2 * r + 1] = t[1];
  }
}

// The reference kernels above, on AVX2 where the processor has it (same bits); has_avx2_kernels():
// whether it does (and AGGLO_NO_AVX2 was not defined at build time).
void gemv2(const double* A, int lda, int rows, int cols, const double* x, double* y);
void gemv2x2(const double* A, int lda, int rows, int cols, const double* x, const double* x2, double* y, double* y2);
bool has_avx2_kernels();

// y[2k], y[2k+1] += sum_r A[r*lda + k] * (v[2r], v[2r+1]),  k < cols (the rows added in order r = 0, 1, ...)
inline void gemv2t_reference(const double* A, int lda, int rows, int cols, const double* v, double* y) {
  const v2d* V = reinterpret_cast<const v2d*>(v);
  v2d* Y = reinterpret_cast<v2d*>(y);
  for (int r = 0; r < rows; ++r) {
    const double* a = A + static_cast<long>(r) * lda;
    const v2d vr = V[r];
    for (int k = 0; k < cols; ++k) Y[k] += a[k] * vr;
  }
}

// gemv2t_reference on AVX2 where the processor has it (same bits).
void gemv2t(const double* A, int lda, int rows, int cols, const double* v, double* y);

}  // namespace agglo::es::sh::kern
