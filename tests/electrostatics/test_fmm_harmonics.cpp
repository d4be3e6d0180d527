// Solid-harmonic identities behind the FMM operators (fmm/solid_harmonics.hpp), checked
// numerically against closed forms and the direct 1/|x - y|.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "agglo/electrostatics/fmm/solid_harmonics.hpp"

using namespace agglo;
using namespace agglo::es::fmm;

TEST(FmmHarmonics, LowOrderClosedForms) {
  const Vec3 x{0.3, -0.7, 0.45};
  const double r2 = norm2(x), r = std::sqrt(r2);
  std::vector<cplx> R(tri_size(3)), I(tri_size(3));
  regular_harmonics(x, 3, R.data());
  irregular_harmonics(x, 3, I.data());
  EXPECT_NEAR(R[tri(0, 0)].real(), 1.0, 1e-15);
  EXPECT_NEAR(R[tri(1, 0)].real(), x.z, 1e-15);
  EXPECT_NEAR(R[tri(1, 1)].real(), -x.x / 2, 1e-15);
  EXPECT_NEAR(R[tri(1, 1)].imag(), -x.y / 2, 1e-15);
  EXPECT_NEAR(R[tri(2, 0)].real(), (3 * x.z * x.z - r2) / 4, 1e-15);
  EXPECT_NEAR(I[tri(0, 0)].real(), 1 / r, 1e-14);
  EXPECT_NEAR(I[tri(1, 0)].real(), x.z / (r2 * r), 1e-14);
  EXPECT_NEAR(I[tri(2, 0)].real(), (3 * x.z * x.z - r2) / (r2 * r2 * r), 1e-13);
  EXPECT_NEAR(I[tri(2, 2)].real(), 3 * (x.x * x.x - x.y * x.y) / (r2 * r2 * r), 1e-13);
}

TEST(FmmHarmonics, AdditionTheoremOfRegularHarmonics) {
  const int p = 8;
  const Vec3 a{0.2, 0.5, -0.3}, b{-0.4, 0.1, 0.6};
  std::vector<cplx> Ra(tri_size(p)), Rb(tri_size(p)), Rab(tri_size(p));
  regular_harmonics(a, p, Ra.data());
  regular_harmonics(b, p, Rb.data());
  regular_harmonics(a + b, p, Rab.data());
  for (int n = 0; n <= p; ++n)
    for (int m = 0; m <= n; ++m) {
      cplx s(0, 0);
      for (int k = 0; k <= n; ++k)
        for (int l = -k; l <= k; ++l) s += coeff(Ra.data(), k, l) * coeff(Rb.data(), n - k, m - l);
      EXPECT_NEAR(std::abs(s - Rab[tri(n, m)]), 0.0, 1e-14) << n << " " << m;
    }
}

TEST(FmmHarmonics, MultipoleExpansionOfInverseDistanceConverges) {
  const Vec3 x{1.1, -0.9, 1.4}, y{0.2, 0.25, -0.15};
  const double exact = 1.0 / norm(x - y);
  double prev_err = 1e300;
  for (int p : {4, 8, 16}) {
    std::vector<cplx> R(tri_size(p)), I(tri_size(p));
    regular_harmonics(y, p, R.data());
    irregular_harmonics(x, p, I.data());
    cplx s(0, 0);
    for (int n = 0; n <= p; ++n)
      for (int m = -n; m <= n; ++m) s += std::conj(coeff(R.data(), n, m)) * coeff(I.data(), n, m);
    const double err = std::abs(s.real() - exact) / exact;
    EXPECT_NEAR(s.imag(), 0.0, 1e-14);
    EXPECT_LT(err, prev_err);
    prev_err = err;
  }
  EXPECT_LT(prev_err, 1e-9);
}

TEST(FmmHarmonics, IrregularTranslation) {
  // I_n^m(D + z) = sum_{k,l} (-1)^k conj(R_k^l(z)) I_{n+k}^{m+l}(D) for |z| < |D|.
  const int p = 3, P = 40;
  const Vec3 D{1.0, 0.8, -1.2}, z{0.1, -0.15, 0.05};
  std::vector<cplx> Iex(tri_size(p)), R(tri_size(P)), I(tri_size(P + p));
  irregular_harmonics(D + z, p, Iex.data());
  regular_harmonics(z, P, R.data());
  irregular_harmonics(D, P + p, I.data());
  for (int n = 0; n <= p; ++n)
    for (int m = 0; m <= n; ++m) {
      cplx s(0, 0);
      for (int k = 0; k <= P; ++k)
        for (int l = -k; l <= k; ++l)
          s += ((k & 1) ? -1.0 : 1.0) * std::conj(coeff(R.data(), k, l)) * coeff(I.data(), n + k, m + l);
      EXPECT_NEAR(std::abs(s - Iex[tri(n, m)]) / std::abs(Iex[tri(0, 0)]), 0.0, 1e-12) << n << " " << m;
    }
}
