// Pair-frame rotation through the shared quarter turns (spectral/pivot_rotation.hpp) against its twin,
// the stored blocks of FrameRotation (rotation.hpp; itself checked against direct evaluation in
// test_spectral_basis.cpp), and the translation of both directions of a pair in one pass against two
// single translations.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "agglo/electrostatics/spectral/harmonics.hpp"
#include "agglo/electrostatics/spectral/pivot_rotation.hpp"
#include "agglo/electrostatics/spectral/translation.hpp"

namespace agglo::es {
namespace {

std::vector<double> pivot_test_vector(int L, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(sh::ncoef(L));
  for (auto& x : v) x = u(rng);
  return v;
}

double pivot_max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::abs(a[k] - b[k]));
  return d;
}

// Degree 47 (the touching pairs' degree at the default target), frame orders all, 25 (those pairs' cut),
// 0; directions random, along +-z (b = 0, pi: the quarter turns must still compose to the identity / a
// half turn) and along x. Both maps of two vectors agree with FrameRotation to 1e-12 (measured: 6e-14
// at L = 30; coefficients O(1)), and Mmax below M cuts both the same way.
TEST(PivotRotation, MatchesStoredBlocks) {
  const int L = 47;
  sh::PivotTables T;
  T.build(L);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> dirs{{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}};
  for (int k = 0; k < 3; ++k) dirs.push_back({u(rng), u(rng), u(rng)});
  double worst = 0.0;
  for (int M : {L, 25, 0})
    for (const Vec3& e : dirs) {
      sh::FrameRotation R;
      R.build(e, L, M);
      sh::PivotRotation P;
      P.build(e, L, M);
      const auto a = pivot_test_vector(L, rng), b = pivot_test_vector(L, rng);
      const int n = sh::ncoef(L), mmax = std::max(0, M - 3);
      std::vector<double> r1(n, 0.0), r2(n, 0.0), p1(n, 0.0), p2(n, 0.0);
      R.to_frame2(L, mmax, a.data(), b.data(), r1.data(), r2.data());
      P.to_frame2(T, L, mmax, a.data(), b.data(), p1.data(), p2.data());
      worst = std::max({worst, pivot_max_difference(r1, p1), pivot_max_difference(r2, p2)});
      std::vector<double> f1(n, 0.5), f2(n, -0.5), g1(n, 0.5), g2(n, -0.5);  // from_frame2 adds
      R.from_frame2(L, mmax, a.data(), b.data(), f1.data(), f2.data());
      P.from_frame2(T, L, mmax, a.data(), b.data(), g1.data(), g2.data());
      worst = std::max({worst, pivot_max_difference(f1, g1), pivot_max_difference(f2, g2)});
      // add = false writes every number of degrees <= L (outputs start as NaN here): the numbers of adding to
      // zeros (== compares -0 and +0 as equal, the one allowed difference)
      const double nan = std::numeric_limits<double>::quiet_NaN();
      for (const bool pivot : {false, true}) {
        std::vector<double> z1(n, 0.0), z2(n, 0.0), w1(n, nan), w2(n, nan);
        if (pivot) {
          P.from_frame2(T, L, mmax, a.data(), b.data(), z1.data(), z2.data());
          P.from_frame2(T, L, mmax, a.data(), b.data(), w1.data(), w2.data(), false);
        } else {
          R.from_frame2(L, mmax, a.data(), b.data(), z1.data(), z2.data());
          R.from_frame2(L, mmax, a.data(), b.data(), w1.data(), w2.data(), false);
        }
        for (int c = 0; c < n; ++c) {
          EXPECT_EQ(w1[c], z1[c]) << "pivot " << pivot << " coefficient " << c;
          EXPECT_EQ(w2[c], z2[c]) << "pivot " << pivot << " coefficient " << c;
        }
      }
    }
  std::printf("largest difference pivot vs stored blocks: %.2e\n", worst);
  EXPECT_LE(worst, 1e-12);
}

// Both directions of a pair in one pass: the same bits as two AxialTranslation::apply calls, with the
// source scalings computed in the call or kept from AxialTranslation::source_powers.
TEST(PivotRotation, PairTranslationIsBitwiseTheTwoSingleOnes) {
  const int L = 47;
  sh::AxialTranslation T;
  T.prepare(L + 8);
  std::mt19937 rng(3);
  const auto a = pivot_test_vector(L, rng), b = pivot_test_vector(L, rng);
  const int n = sh::ncoef(L);
  for (int M : {L, 25}) {
    std::vector<double> x1(n, 0.25), x2(n, 0.25), y1(n, 0.25), y2(n, 0.25), z1(n, 0.25), z2(n, 0.25), powers;
    T.apply(L, M, 0.49, 0.3, +1, b.data(), x1.data());
    T.apply(L, M, 0.3, 0.49, -1, a.data(), x2.data());
    T.apply_pair(L, M, 0.49, 0.3, b.data(), a.data(), y1.data(), y2.data());
    sh::AxialTranslation::source_powers(std::min(L, M), 0.49, 0.3, powers);
    T.apply_pair(L, M, 0.49, 0.3, b.data(), a.data(), z1.data(), z2.data(), powers.data());
    for (int k = 0; k < n; ++k) {
      ASSERT_EQ(x1[k], y1[k]) << "M " << M << " coefficient " << k;
      ASSERT_EQ(x2[k], y2[k]) << "M " << M << " coefficient " << k;
      ASSERT_EQ(x1[k], z1[k]) << "M " << M << " coefficient " << k;
      ASSERT_EQ(x2[k], z2[k]) << "M " << M << " coefficient " << k;
    }
    EXPECT_NE(x1[sh::idx(3, 2)], 0.25);  // the translation reached the output
  }
}

}  // namespace
}  // namespace agglo::es
