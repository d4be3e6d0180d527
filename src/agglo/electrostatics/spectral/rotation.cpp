#include "agglo/electrostatics/spectral/rotation.hpp"

#include <cmath>

#include "agglo/electrostatics/spectral/harmonics.hpp"

namespace agglo::es::sh {

void FrameRotation::build(const Vec3& e, int L) {
  L_ = L;
  const double rxy = std::hypot(e.x, e.y);
  const double a = (rxy > 0) ? std::atan2(e.y, e.x) : 0.0;
  const double b = std::atan2(rxy, e.z);
  cosa_.resize(L + 1);
  sina_.resize(L + 1);
  for (int m = 0; m <= L; ++m) {
    cosa_[m] = std::cos(m * a);
    sina_[m] = std::sin(m * a);
  }
  // Wigner d^j_{a b}(beta), a >= |b|, j = 0..L. Offsets: sum_{k<j} (k+1)^2.
  std::vector<std::size_t> doff(L + 2, 0);
  for (int j = 0; j <= L; ++j) doff[j + 1] = doff[j] + std::size_t(j + 1) * (j + 1);
  d_.assign(doff[L + 1], 0.0);
  auto D = [&](int j, int p, int q) -> double& { return d_[doff[j] + p * p + p + q]; };
  const double cb = std::cos(b), ch = std::cos(0.5 * b), sh = std::sin(0.5 * b);
  for (int p = 0; p <= L; ++p) {
    for (int q = -p; q <= p; ++q) {
      // start: d^p_{p q} = (-1)^(p-q) sqrt((2p)!/((p+q)!(p-q)!)) c^(p+q) s^(p-q)
      double lb = 0.5 * (std::lgamma(2.0 * p + 1) - std::lgamma(p + q + 1.0) - std::lgamma(p - q + 1.0));
      double v = std::exp(lb) * std::pow(ch, p + q) * std::pow(sh, p - q);
      if ((p - q) & 1) v = -v;
      D(p, p, q) = v;
      double prev = 0.0, cur = v;
      for (int j = p; j < L; ++j) {
        double next;
        if (j == 0) {
          next = cb;  // d^1_00
        } else {
          double jj = j;
          double c1 = (2 * jj + 1) * (jj * (jj + 1) * cb - double(p) * q);
          double c2 = (jj + 1) * std::sqrt((jj * jj - q * q) * (jj * jj - double(p) * p));
          double c0 = jj * std::sqrt(((jj + 1) * (jj + 1) - q * q) * ((jj + 1) * (jj + 1) - double(p) * p));
          next = (c1 * cur - c2 * prev) / c0;
        }
        D(j + 1, p, q) = next;
        prev = cur;
        cur = next;
      }
    }
  }
  // d^j_{m' m} for any |m'|, |m| <= j from the stored region m' >= |m|:
  // d_{m'm} = (-1)^(m-m') d_{m m'} = d_{-m,-m'}.
  auto d = [&](int j, int mp, int m) -> double {
    auto sgn = [](int k) { return (k & 1) ? -1.0 : 1.0; };
    if (mp >= std::abs(m)) return D(j, mp, m);
    if (-mp >= std::abs(m)) return sgn(-mp + m) * D(j, -mp, -m);  // d_{mp,m} = d_{-m,-mp} = (-1)^(-mp+m) d_{-mp,-m}
    if (m >= 0) return sgn(m - mp) * D(j, m, mp);                  // |m| > |mp|
    return D(j, -m, -mp);                                          // d_{mp,m} = d_{-m,-mp}
  };
  // Real blocks. G_{m' m} = coefficient of Z_{m'} in Z_m(R^{-1} x), R = R_y(b), orthonormal real Z;
  // in our basis (Y = Z * s_m * const, s_0 = 1, s_m = 1/sqrt2) the frame map is
  // c'_{m'} = sum_m G_{m m'} (s_m / s_{m'}) c_m.
  off_.assign(L + 2, 0);
  for (int l = 0; l <= L; ++l) off_[l + 1] = off_[l] + (l + 1) * (l + 1) + l * l;
  blk_.assign(off_[L + 1], 0.0);
  const double r2 = std::sqrt(2.0);
  auto sgn = [](int k) { return (k & 1) ? -1.0 : 1.0; };
  for (int l = 0; l <= L; ++l) {
    double* C = &blk_[off_[l]];
    double* S = C + (l + 1) * (l + 1);
    auto Gc = [&](int mp, int m) -> double {  // cos block, m', m >= 0
      if (m > 0 && mp > 0) return sgn(m + mp) * d(l, mp, m) + sgn(mp) * d(l, mp, -m);
      if (m > 0) return r2 * sgn(m) * d(l, 0, m);
      if (mp > 0) return r2 * sgn(mp) * d(l, mp, 0);
      return d(l, 0, 0);
    };
    auto Gs = [&](int mp, int m) -> double {  // sin block, m', m >= 1
      return sgn(m + mp) * d(l, mp, m) - sgn(mp) * d(l, mp, -m);
    };
    auto s = [&](int m) { return m == 0 ? 1.0 : 1.0 / r2; };
    for (int mp = 0; mp <= l; ++mp)
      for (int m = 0; m <= l; ++m) C[mp * (l + 1) + m] = Gc(m, mp) * s(m) / s(mp);
    for (int mp = 1; mp <= l; ++mp)
      for (int m = 1; m <= l; ++m) S[(mp - 1) * l + (m - 1)] = Gs(m, mp);
  }
}

void FrameRotation::to_frame(int Lmax, const double* in, double* out) const {
  double tmp[2 * 512 + 2];
  for (int l = 0; l <= Lmax; ++l) {
    // z rotation: c'^c = c^c cos ma + c^s sin ma, c'^s = -c^c sin ma + c^s cos ma
    double* tc = tmp;          // m = 0..l
    double* ts = tmp + l + 1;  // m = 1..l at ts[m-1]
    tc[0] = in[idx(l, 0)];
    for (int m = 1; m <= l; ++m) {
      double cc = in[idx(l, m)], ss = in[idx(l, -m)];
      tc[m] = cc * cosa_[m] + ss * sina_[m];
      ts[m - 1] = -cc * sina_[m] + ss * cosa_[m];
    }
    const double* C = &blk_[off_[l]];
    const double* S = C + (l + 1) * (l + 1);
    for (int mp = 0; mp <= l; ++mp) {
      const double* row = C + mp * (l + 1);
      double acc = 0.0;
      for (int m = 0; m <= l; ++m) acc += row[m] * tc[m];
      out[idx(l, mp)] = acc;
    }
    for (int mp = 1; mp <= l; ++mp) {
      const double* row = S + (mp - 1) * l;
      double acc = 0.0;
      for (int m = 0; m < l; ++m) acc += row[m] * ts[m];
      out[idx(l, -mp)] = acc;
    }
  }
}

void FrameRotation::from_frame(int Lmax, const double* in, double* out) const {
  double tmp[2 * 512 + 2];
  for (int l = 0; l <= Lmax; ++l) {
    const double* C = &blk_[off_[l]];
    const double* S = C + (l + 1) * (l + 1);
    double* tc = tmp;
    double* ts = tmp + l + 1;
    for (int m = 0; m <= l; ++m) tc[m] = 0.0;
    for (int m = 0; m < l; ++m) ts[m] = 0.0;
    // Cos block C = s^-1 G^T s with G orthogonal: C^-1 = s^-2 C^T s^2 (s_0 = 1, s_m = 1/sqrt2).
    for (int mp = 0; mp <= l; ++mp) {
      const double* row = C + mp * (l + 1);
      double v = in[idx(l, mp)] * (mp == 0 ? 2.0 : 1.0);
      for (int m = 0; m <= l; ++m) tc[m] += row[m] * v;
    }
    tc[0] *= 0.5;
    for (int mp = 1; mp <= l; ++mp) {
      const double* row = S + (mp - 1) * l;
      double v = in[idx(l, -mp)];
      for (int m = 0; m < l; ++m) ts[m] += row[m] * v;
    }
    out[idx(l, 0)] = tc[0];
    for (int m = 1; m <= l; ++m) {
      out[idx(l, m)] = tc[m] * cosa_[m] - ts[m - 1] * sina_[m];
      out[idx(l, -m)] = tc[m] * sina_[m] + ts[m - 1] * cosa_[m];
    }
  }
}

}  // namespace agglo::es::sh
