// The spectral solver's dense kernels (spectral/dense_ops.hpp): gemv2, gemv2x2 and gemv2t, on AVX2 where the
// processor has it, give the two-lane reference kernels' results bit for bit, for every shape the
// rotations and translations use (rows and columns from 0, columns not a multiple of four, leading
// dimension above the columns, inputs with signed zeros and values of very different size).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <random>
#include <vector>

#include "agglo/electrostatics/spectral/dense_ops.hpp"

namespace agglo::es {
namespace {

std::vector<double> dense_ops_random(std::size_t n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-30, 30);
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = k % 7 == 3 ? -0.0 : std::ldexp(u(rng), e(rng));
  return v;
}

bool dense_ops_same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  // (memcmp must not see the null data() of an empty vector: UBSan's nonnull-attribute check)
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

TEST(DenseOps, KernelsAreBitwiseTheReference) {
  std::mt19937 rng(17);
  int shapes = 0, nonzero = 0, changed_t = 0;
  for (int rows : {0, 1, 2, 3, 5, 8, 25, 48})
    for (int cols : {0, 1, 2, 3, 4, 5, 7, 8, 11, 24, 25, 48}) {
      const int lda = cols + 3;
      const auto A = dense_ops_random(std::size_t(rows) * lda, rng);
      const auto x = dense_ops_random(2 * std::size_t(cols), rng), x2 = dense_ops_random(2 * std::size_t(cols), rng);
      std::vector<double> y(2 * std::size_t(rows), 9.0), y_ref = y, y2 = y, y2_ref = y, z = y, z_ref = y;
      // gemv2t: y (cols pairs, nonzero start: it adds) += A^T v, v of rows pairs
      const auto vt = dense_ops_random(2 * std::size_t(rows), rng);
      std::vector<double> t = dense_ops_random(2 * std::size_t(cols), rng), t_ref = t, t_start = t;
      sh::kern::gemv2t(A.data(), lda, rows, cols, vt.data(), t.data());
      sh::kern::gemv2t_reference(A.data(), lda, rows, cols, vt.data(), t_ref.data());
      EXPECT_TRUE(dense_ops_same_bits(t, t_ref)) << "gemv2t " << rows << " x " << cols;
      for (std::size_t i = 0; i < t.size(); ++i) changed_t += (t[i] != t_start[i]);
      sh::kern::gemv2(A.data(), lda, rows, cols, x.data(), z.data());
      sh::kern::gemv2_reference(A.data(), lda, rows, cols, x.data(), z_ref.data());
      sh::kern::gemv2x2(A.data(), lda, rows, cols, x.data(), x2.data(), y.data(), y2.data());
      sh::kern::gemv2x2_reference(A.data(), lda, rows, cols, x.data(), x2.data(), y_ref.data(), y2_ref.data());
      EXPECT_TRUE(dense_ops_same_bits(z, z_ref)) << rows << " x " << cols;
      EXPECT_TRUE(dense_ops_same_bits(y, y_ref)) << rows << " x " << cols;
      EXPECT_TRUE(dense_ops_same_bits(y2, y2_ref)) << rows << " x " << cols;
      EXPECT_TRUE(dense_ops_same_bits(y, z)) << rows << " x " << cols;  // gemv2x2's first pair is gemv2's
      for (double v : z) nonzero += (v != 0.0 && v != 9.0);
      ++shapes;
    }
  EXPECT_EQ(shapes, 96);
  EXPECT_GT(nonzero, 1000);  // the comparison saw results, not only untouched outputs
  EXPECT_GT(changed_t, 1000);  // gemv2t added something to most of its outputs
  std::cout << "AVX2 kernels: " << (sh::kern::has_avx2_kernels() ? "yes" : "no (reference kernels)") << "\n";
}

}  // namespace
}  // namespace agglo::es
