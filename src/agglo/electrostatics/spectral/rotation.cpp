#include "agglo/electrostatics/spectral/rotation.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/electrostatics/spectral/harmonics.hpp"
#include "agglo/electrostatics/spectral/dense_ops.hpp"

namespace agglo::es::sh {

namespace {
// Dot product with four independent accumulators (lets the compiler pipeline/vectorise).
inline double dot4(const double* a, const double* b, int n) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    s0 += a[k] * b[k];
    s1 += a[k + 1] * b[k + 1];
    s2 += a[k + 2] * b[k + 2];
    s3 += a[k + 3] * b[k + 3];
  }
  for (; k < n; ++k) s0 += a[k] * b[k];
  return (s0 + s1) + (s2 + s3);
}
// Two dot products sharing the row a.
inline void dot4x2(const double* a, const double* b, const double* c, int n, double& rb, double& rc) {
  double b0 = 0, b1 = 0, c0 = 0, c1 = 0;
  int k = 0;
  for (; k + 2 <= n; k += 2) {
    b0 += a[k] * b[k];
    c0 += a[k] * c[k];
    b1 += a[k + 1] * b[k + 1];
    c1 += a[k + 1] * c[k + 1];
  }
  for (; k < n; ++k) {
    b0 += a[k] * b[k];
    c0 += a[k] * c[k];
  }
  rb = b0 + b1;
  rc = c0 + c1;
}
}  // namespace

void FrameRotation::build(const Vec3& e, int L, int M) {
  L_ = L;
  M_ = (M < 0 || M > L) ? L : M;
  const double rxy = std::hypot(e.x, e.y);
  const double a = (rxy > 0) ? std::atan2(e.y, e.x) : 0.0;
  const double b = std::atan2(rxy, e.z);
  cosa_.resize(L + 1);
  sina_.resize(L + 1);
  for (int m = 0; m <= L; ++m) {
    cosa_[m] = std::cos(m * a);
    sina_[m] = std::sin(m * a);
  }
  // The recurrence tables and the Wigner d of one build depend on L only or are scratch: one set per
  // thread (the pairs of a solve are built in parallel), not one per pair.
  thread_local RotationTables tables;
  thread_local std::vector<double> d;
  grow_tables(tables, L);
  std::vector<std::size_t> doff(L + 2, 0);
  for (int j = 0; j <= L; ++j) doff[j + 1] = doff[j] + std::size_t(j + 1) * (j + 1);
  d.resize(doff[L + 1]);
  wigner_d(b, doff, tables, d);
  real_blocks(doff, d);
}

// log k! and the square roots sqrt(j^2 - m^2) (with inverses) used by the d recurrence; grow only.
void grow_tables(RotationTables& t, int L) {
  if (static_cast<int>(t.lf.size()) < 2 * L + 2) {
    t.lf.resize(2 * L + 2);
    for (int k = 0; k < 2 * L + 2; ++k) t.lf[k] = std::lgamma(k + 1.0);
  }
  if (t.sqL < L + 1) {
    t.sqL = L + 1;
    t.sq.assign(std::size_t(t.sqL + 1) * (t.sqL + 1), 0.0);
    t.isq.assign(t.sq.size(), 0.0);
    t.ij.assign(t.sqL + 1, 0.0);
    for (int j = 0; j <= t.sqL; ++j) {
      t.ij[j] = j > 0 ? 1.0 / j : 0.0;
      for (int m = 0; m <= j; ++m) {
        double v = std::sqrt(double(j * j - m * m));
        t.sq[std::size_t(j) * (t.sqL + 1) + m] = v;
        t.isq[std::size_t(j) * (t.sqL + 1) + m] = v > 0 ? 1.0 / v : 0.0;
      }
    }
  }
}

// Wigner d^j_{p q}(b), p >= |q|, j = 0..L_, into d at doff[j] + p^2 + p + q (doff[j] = sum_{k<j} (k+1)^2).
void FrameRotation::wigner_d(double b, const std::vector<std::size_t>& doff, const RotationTables& t,
                             std::vector<double>& d) const {
  const int L = L_;
  const double cb = std::cos(b), ch = std::cos(0.5 * b), sh = std::sin(0.5 * b);
  const double lc = std::log(ch), ls = std::log(sh);
  const std::size_t S1 = std::size_t(t.sqL) + 1;
  // Three-term recurrence in j for every (p, q); the chains of one p (all q) are independent and
  // advanced together so that the processor overlaps them. Index of d^j_{pq}: doff[j] + p^2 + p + q.
  std::vector<double> prev(2 * L + 1), cur(2 * L + 1), c2q(2 * L + 1), icq(2 * L + 1);
  for (int p = 0; p <= L; ++p) {
    const int qm = std::min(p, M_);  // only |q| <= M is needed for frame orders <= M
    const int nq = 2 * qm + 1;
    for (int q = -qm; q <= qm; ++q) {
      // start: d^p_{p q} = (-1)^(p-q) sqrt((2p)!/((p+q)!(p-q)!)) c^(p+q) s^(p-q)
      double e = 0.5 * (t.lf[2 * p] - t.lf[p + q] - t.lf[p - q]);
      if (p + q > 0) e += (p + q) * lc;
      if (p - q > 0) e += (p - q) * ls;
      double v = std::exp(e);
      if ((p - q) & 1) v = -v;
      d[doff[p] + std::size_t(p * p + p + q)] = v;
      prev[q + qm] = 0.0;
      cur[q + qm] = v;
    }
    for (int j = p; j < L; ++j) {
      double* out = &d[doff[j + 1] + std::size_t(p * p + p - qm)];
      if (j == 0) {  // p = q = 0: d^1_00
        out[0] = cb;
        prev[0] = cur[0];
        cur[0] = cb;
        continue;
      }
      const double jj = j;
      const double sjp = t.sq[std::size_t(j) * S1 + p], isjp = t.isq[std::size_t(j + 1) * S1 + p];
      const double tj = jj * (jj + 1) * cb;
      for (int k = 0; k < nq; ++k) {
        const int aq = std::abs(k - qm);
        c2q[k] = (jj + 1) * t.sq[std::size_t(j) * S1 + aq] * sjp;
        icq[k] = t.ij[j] * t.isq[std::size_t(j + 1) * S1 + aq] * isjp;
      }
      for (int k = 0; k < nq; ++k) {
        const double c1 = (2 * jj + 1) * (tj - double(p) * (k - qm));
        const double next = (c1 * cur[k] - c2q[k] * prev[k]) * icq[k];
        out[k] = next;
        prev[k] = cur[k];
        cur[k] = next;
      }
    }
  }
}

// The real cos/sin blocks of every degree (blk_, off_) from d_.
void FrameRotation::real_blocks(const std::vector<std::size_t>& doff, const std::vector<double>& d) {
  const int L = L_;
  // Real blocks. G_{m' m} = coefficient of Z_{m'} in Z_m(R^{-1} x), R = R_y(b), orthonormal real Z;
  // in our basis (Y = Z * s_m * const, s_0 = 1, s_m = 1/sqrt2) the frame map is
  // c'_{m'} = sum_m G_{m m'} (s_m / s_{m'}) c_m. Needed: d^l_{m, +-m'} for m' <= min(l, M), read
  // from the stored region (first index >= |second|) with d_{m m'} = (-1)^(m'-m) d_{m' m} and
  // d_{m,-m'} = d_{m',-m} (both for m < m').
  off_.assign(L + 2, 0);
  for (int l = 0; l <= L; ++l) {
    int ml = std::min(l, M_);
    off_[l + 1] = off_[l] + (ml + 1) * (l + 1) + ml * l;
  }
  blk_.assign(off_[L + 1], 0.0);
  const double r2 = std::sqrt(2.0), ir2 = 1.0 / r2;
  auto sgn = [](int k) { return (k & 1) ? -1.0 : 1.0; };
  for (int l = 0; l <= L; ++l) {
    double* C = &blk_[off_[l]];
    const int ml = std::min(l, M_);
    double* S = C + (ml + 1) * (l + 1);
    const double* Dl = &d[doff[l]];
    auto at = [Dl](int p, int q) { return Dl[p * p + p + q]; };
    // m' = 0 row: G(m, 0) s_m.
    C[0] = at(0, 0);
    for (int m = 1; m <= l; ++m) C[m] = r2 * sgn(m) * at(m, 0) * ir2;
    for (int mp = 1; mp <= ml; ++mp) {
      double* Cr = C + mp * (l + 1);
      double* Sr = S + (mp - 1) * l;
      Cr[0] = r2 * sgn(mp) * (sgn(mp) * at(mp, 0)) / ir2;
      for (int m = 1; m <= l; ++m) {
        double dpos, dneg;  // d^l_{m, m'}, d^l_{m, -m'}
        if (m >= mp) {
          dpos = at(m, mp);
          dneg = at(m, -mp);
        } else {
          dpos = sgn(mp - m) * at(mp, m);
          dneg = at(mp, -m);
        }
        Cr[m] = (sgn(m + mp) * dpos + sgn(m) * dneg) * ir2 / ir2;
        Sr[m - 1] = sgn(m + mp) * dpos - sgn(m) * dneg;
      }
    }
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
    const int ml = std::min(l, M_);
    const double* S = C + (ml + 1) * (l + 1);
    for (int mp = 0; mp <= ml; ++mp) out[idx(l, mp)] = dot4(C + mp * (l + 1), tc, l + 1);
    for (int mp = 1; mp <= ml; ++mp) out[idx(l, -mp)] = dot4(S + (mp - 1) * l, ts, l);
  }
}

void FrameRotation::from_frame(int Lmax, const double* in, double* out) const {
  double tmp[2 * 512 + 2];
  for (int l = 0; l <= Lmax; ++l) {
    const double* C = &blk_[off_[l]];
    const int ml = std::min(l, M_);
    const double* S = C + (ml + 1) * (l + 1);
    double* tc = tmp;
    double* ts = tmp + l + 1;
    for (int m = 0; m <= l; ++m) tc[m] = 0.0;
    for (int m = 0; m < l; ++m) ts[m] = 0.0;
    // Cos block C = s^-1 G^T s with G orthogonal: C^-1 = s^-2 C^T s^2 (s_0 = 1, s_m = 1/sqrt2).
    for (int mp = 0; mp <= ml; ++mp) {
      const double* row = C + mp * (l + 1);
      double v = in[idx(l, mp)] * (mp == 0 ? 2.0 : 1.0);
      for (int m = 0; m <= l; ++m) tc[m] += row[m] * v;
    }
    tc[0] *= 0.5;
    for (int mp = 1; mp <= ml; ++mp) {
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

void FrameRotation::to_frame2(int Lmax, int Mmax, const double* in1, const double* in2, double* out1,
                              double* out2) const {
  alignas(16) double tc[2 * 514], ts[2 * 514], yc[2 * 514], ys[2 * 514];
  for (int l = 0; l <= Lmax; ++l) {
    // z rotation, interleaving the two vectors
    tc[0] = in1[idx(l, 0)];
    tc[1] = in2[idx(l, 0)];
    for (int m = 1; m <= l; ++m) {
      double a = in1[idx(l, m)], b = in1[idx(l, -m)];
      tc[2 * m] = a * cosa_[m] + b * sina_[m];
      ts[2 * (m - 1)] = -a * sina_[m] + b * cosa_[m];
      a = in2[idx(l, m)], b = in2[idx(l, -m)];
      tc[2 * m + 1] = a * cosa_[m] + b * sina_[m];
      ts[2 * (m - 1) + 1] = -a * sina_[m] + b * cosa_[m];
    }
    const int ml = std::min(l, M_);
    const int mm = std::min(ml, Mmax);
    const double* C = &blk_[off_[l]];
    const double* S = C + (ml + 1) * (l + 1);
    kern::gemv2(C, l + 1, mm + 1, l + 1, tc, yc);
    for (int mp = 0; mp <= mm; ++mp) {
      out1[idx(l, mp)] = yc[2 * mp];
      out2[idx(l, mp)] = yc[2 * mp + 1];
    }
    if (mm > 0) {
      kern::gemv2(S, l, mm, l, ts, ys);
      for (int mp = 1; mp <= mm; ++mp) {
        out1[idx(l, -mp)] = ys[2 * (mp - 1)];
        out2[idx(l, -mp)] = ys[2 * (mp - 1) + 1];
      }
    }
  }
}

void FrameRotation::from_frame2(int Lmax, int Mmax, const double* in1, const double* in2, double* out1,
                                double* out2, bool add) const {
  auto put = [add](double& o, double v) { o = add ? o + v : v; };
  alignas(16) double vc[2 * 514], vs[2 * 514], tc[2 * 514], ts[2 * 514];
  for (int l = 0; l <= Lmax; ++l) {
    const int ml = std::min(l, M_);
    const int mm = std::min(ml, Mmax);
    const double* C = &blk_[off_[l]];
    const double* S = C + (ml + 1) * (l + 1);
    // Cos block C = s^-1 G^T s with G orthogonal: C^-1 = s^-2 C^T s^2 (s_0 = 1, s_m = 1/sqrt2).
    for (int mp = 0; mp <= mm; ++mp) {
      double w = (mp == 0 ? 2.0 : 1.0);
      vc[2 * mp] = in1[idx(l, mp)] * w;
      vc[2 * mp + 1] = in2[idx(l, mp)] * w;
    }
    for (int m = 0; m < 2 * (l + 1); ++m) tc[m] = 0.0;
    kern::gemv2t(C, l + 1, mm + 1, l + 1, vc, tc);
    tc[0] *= 0.5;
    tc[1] *= 0.5;
    for (int m = 0; m < 2 * l; ++m) ts[m] = 0.0;
    if (mm > 0) {
      for (int mp = 1; mp <= mm; ++mp) {
        vs[2 * (mp - 1)] = in1[idx(l, -mp)];
        vs[2 * (mp - 1) + 1] = in2[idx(l, -mp)];
      }
      kern::gemv2t(S, l, mm, l, vs, ts);
    }
    put(out1[idx(l, 0)], tc[0]);
    put(out2[idx(l, 0)], tc[1]);
    for (int m = 1; m <= l; ++m) {
      const double c = cosa_[m], s = sina_[m];
      put(out1[idx(l, m)], tc[2 * m] * c - ts[2 * (m - 1)] * s);
      put(out1[idx(l, -m)], tc[2 * m] * s + ts[2 * (m - 1)] * c);
      put(out2[idx(l, m)], tc[2 * m + 1] * c - ts[2 * (m - 1) + 1] * s);
      put(out2[idx(l, -m)], tc[2 * m + 1] * s + ts[2 * (m - 1) + 1] * c);
    }
  }
}

}  // namespace agglo::es::sh
