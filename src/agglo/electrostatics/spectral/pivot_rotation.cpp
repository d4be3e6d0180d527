// Pair-frame rotation through two shared quarter turns; see pivot_rotation.hpp.
#include "agglo/electrostatics/spectral/pivot_rotation.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"
#include "agglo/electrostatics/spectral/dense_ops.hpp"
#include "agglo/electrostatics/spectral/harmonics.hpp"

namespace agglo::es::sh {

namespace {

// Buffers of one degree l, two interleaved vectors (v = 0, 1), ordered by parity of m: cos parts at
// c[2 pivot_cpos(l, m) + v] (m = 0..l: even m, then odd m), sin parts at s[2 pivot_spos(l, m) + v]
// (m = 1..l: even m, then odd m).
struct PivotBuffers {
  alignas(16) double c[2 * 514], s[2 * 514], yc[2 * 514], ys[2 * 514];
};

// Orders m <= last of parity q: from 0 (cos parts) or from 1 (sin parts).
int pivot_ccount(int q, int last) { return last < q ? 0 : (last - q) / 2 + 1; }
int pivot_scount(int q, int last) {
  const int first = q ? 1 : 2;
  return last < first ? 0 : (last - first) / 2 + 1;
}
int pivot_coff(int l, int q) { return q ? pivot_ccount(0, l) : 0; }
int pivot_soff(int l, int q) { return q ? pivot_scount(0, l) : 0; }
int pivot_cpos(int l, int m) { return pivot_coff(l, m & 1) + m / 2; }
int pivot_spos(int l, int m) { return pivot_soff(l, m & 1) + (m & 1 ? (m - 1) / 2 : m / 2 - 1); }

// The z turns below (pivot_turn_forward, pivot_turn_inverse) in two versions, for AVX2 where the processor
// has it (four numbers a step) and the baseline; no fused multiply-add in either, so the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(AGGLO_NO_AVX2)
#define AGGLO_PIVOT_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define AGGLO_PIVOT_CLONES
#endif

// Orders 0..mc of degree l of in1, in2 into c, s (the other orders of c, s set to zero), one parity run at
// a time (pivot_cpos, pivot_spos).
void pivot_load(int l, int mc, const double* in1, const double* in2, double* c, double* s) {
  for (int q = 0; q < 2; ++q) {
    double* cp = c + 2 * pivot_coff(l, q);
    int m = q;
    for (; m <= mc; m += 2, cp += 2) cp[0] = in1[idx(l, m)], cp[1] = in2[idx(l, m)];
    for (; m <= l; m += 2, cp += 2) cp[0] = cp[1] = 0.0;
    double* sp = s + 2 * pivot_soff(l, q);
    for (m = 2 - q; m <= mc; m += 2, sp += 2) sp[0] = in1[idx(l, -m)], sp[1] = in2[idx(l, -m)];
    for (; m <= l; m += 2, sp += 2) sp[0] = sp[1] = 0.0;
  }
}

// Orders 0..mc of c, s into degree l of out1, out2 (written, or added with `add`), one parity run at a time.
void pivot_store(int l, int mc, const double* c, const double* s, bool add, double* out1, double* out2) {
  auto put = [add](double& o, double v) { o = add ? o + v : v; };
  for (int q = 0; q < 2; ++q) {
    const double* cp = c + 2 * pivot_coff(l, q);
    for (int m = q; m <= mc; m += 2, cp += 2) put(out1[idx(l, m)], cp[0]), put(out2[idx(l, m)], cp[1]);
    const double* sp = s + 2 * pivot_soff(l, q);
    for (int m = 2 - q; m <= mc; m += 2, sp += 2) put(out1[idx(l, -m)], sp[0]), put(out2[idx(l, -m)], sp[1]);
  }
}

// z rotation of orders 1..mc in place: forward (FrameRotation::to_frame: c' = c cos + s sin,
// s' = -c sin + s cos) or its inverse (from_frame: c = c' cos - s' sin, s = c' sin + s' cos).
// Orders of one parity q are contiguous in c and s (pivot_cpos, pivot_spos) and in the table (TurnTable),
// so each parity is one element-wise pass from its first order m0 = 2 - q (the same arithmetic per order,
// so the same bits, as one loop over m = 1..mc: a sign flip of a product is exact).
template <bool Inverse>
inline __attribute__((always_inline)) void pivot_turn_runs(int l, int mc, const TurnTable& t, double* c, double* s) {
  for (int q = 0; q < 2; ++q) {
    const int n = 2 * (q ? (mc + 1) / 2 : mc / 2);
    double* __restrict cp = c + 2 * pivot_cpos(l, 2 - q);
    double* __restrict sp = s + 2 * pivot_spos(l, 2 - q);
    const double* __restrict cs = t.run(false, q);
    const double* __restrict sn = t.run(true, q);
    for (int e = 0; e < n; ++e) {
      const double x = cp[e], y = sp[e];
      cp[e] = Inverse ? x * cs[e] - y * sn[e] : x * cs[e] + y * sn[e];
      sp[e] = Inverse ? x * sn[e] + y * cs[e] : y * cs[e] - x * sn[e];
    }
  }
}

AGGLO_PIVOT_CLONES void pivot_turn_forward(int l, int mc, const TurnTable& t, double* c, double* s) {
  pivot_turn_runs<false>(l, mc, t, c, s);
}
AGGLO_PIVOT_CLONES void pivot_turn_inverse(int l, int mc, const TurnTable& t, double* c, double* s) {
  pivot_turn_runs<true>(l, mc, t, c, s);
}

// Quarter turn Y of degree l (to_frame blocks): orders <= mo of yc, ys from the orders <= mc of c, s.
void pivot_forward(const PivotTables& T, int l, int mc, int mo, const double* c, const double* s, double* yc,
                   double* ys) {
  for (int pr = 0; pr < 2; ++pr) {
    const int qc = (l + pr) % 2, qs = (l + pr + 1) % 2;
    const PivotTables::Half hc = T.half(l, false, pr), hs = T.half(l, true, pr);
    kern::gemv2(hc.a, hc.columns, pivot_ccount(pr, mo), pivot_ccount(qc, mc), c + 2 * pivot_coff(l, qc),
                yc + 2 * pivot_coff(l, pr));
    kern::gemv2(hs.a, hs.columns, pivot_scount(pr, mo), pivot_scount(qs, mc), s + 2 * pivot_soff(l, qs),
                ys + 2 * pivot_soff(l, pr));
  }
}

// Inverse quarter turn Y^-1 of degree l (the transposed halves, PivotTables) from all orders of c, s
// into orders <= mo of yc, ys. The output parity qc takes the rows of parity pr of Y.
void pivot_backward(const PivotTables& T, int l, int mo, const double* c, const double* s, double* yc, double* ys) {
  for (int pr = 0; pr < 2; ++pr) {
    const int qc = (l + pr) % 2, qs = (l + pr + 1) % 2;
    const PivotTables::Half hc = T.half(l, false, pr, true), hs = T.half(l, true, pr, true);
    kern::gemv2(hc.a, hc.columns, pivot_ccount(qc, mo), pivot_ccount(pr, l), c + 2 * pivot_coff(l, pr),
                yc + 2 * pivot_coff(l, qc));
    kern::gemv2(hs.a, hs.columns, pivot_scount(qs, mo), pivot_scount(pr, l), s + 2 * pivot_soff(l, pr),
                ys + 2 * pivot_soff(l, qs));
  }
}

}  // namespace

void PivotTables::build(int L) {
  FrameRotation Y;
  Y.build(Vec3{1.0, 0.0, 0.0}, L, L);
  L_ = L;
  off_.assign(8 * std::size_t(L + 1) + 1, 0);
  ld_.assign(8 * std::size_t(L + 1), 0);
  q_.clear();
  for (int l = 0; l <= L; ++l)
    for (int k = 0; k < 8; ++k) {
      const bool sin = (k / 2) % 2, transposed = k >= 4;
      const int pr = k % 2, q = (l + pr + (sin ? 1 : 0)) % 2;
      const std::size_t slot = std::size_t(8 * l + k);
      const int rows = sin ? pivot_scount(pr, l) : pivot_ccount(pr, l);
      const int cols = sin ? pivot_scount(q, l) : pivot_ccount(q, l);
      ld_[slot] = transposed ? rows : cols;
      std::vector<double> h(std::size_t(rows) * cols);
      for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j) {
          // row m' and column m of the full block (sin rows and columns start at order 1)
          const int r = sin ? (pr ? 1 : 2) + 2 * i : pr + 2 * i, m = sin ? (q ? 1 : 2) + 2 * j : q + 2 * j;
          const double y = sin ? Y.sin_block(l)[(r - 1) * l + (m - 1)] : Y.cos_block(l)[r * (l + 1) + m];
          // the inverse of the cos block is s^-2 C^T s^2 (s_0 = 1, s_m = 1/sqrt2; FrameRotation::from_frame)
          const double w = (!sin && r == 0 ? 2.0 : 1.0) * (!sin && m == 0 ? 0.5 : 1.0);
          if (transposed)
            h[std::size_t(j) * rows + i] = w * y;
          else
            h[std::size_t(i) * cols + j] = y;
        }
      q_.insert(q_.end(), h.begin(), h.end());
      off_[slot + 1] = q_.size();
    }
  std::vector<double> cq(L + 1), sq(L + 1);
  constexpr double kc[4] = {1.0, 0.0, -1.0, 0.0}, ks[4] = {0.0, -1.0, 0.0, 1.0};  // cos, sin(-m pi/2)
  for (int m = 0; m <= L; ++m) {
    cq[m] = kc[m % 4];
    sq[m] = ks[m % 4];
  }
  quarter_.build(L, cq.data(), sq.data());
}

void TurnTable::build(int L, const double* cs, const double* sn) {
  odd = 2 * (L / 2 + 1);
  c.assign(std::size_t(odd + 2 * ((L + 1) / 2)), 0.0);
  s.assign(c.size(), 0.0);
  for (int m = 0; m <= L; ++m) {
    const std::size_t at = std::size_t(m % 2 ? odd + m - 1 : m);
    c[at] = c[at + 1] = cs[m];
    s[at] = s[at + 1] = sn[m];
  }
}

void PivotRotation::build(const Vec3& e, int L, int M) {
  L_ = L;
  M_ = (M < 0 || M > L) ? L : M;
  const double rxy = std::hypot(e.x, e.y);
  const double a = ((rxy > 0) ? std::atan2(e.y, e.x) : 0.0) + 0.5 * constants::pi;
  const double b = std::atan2(rxy, e.z);
  std::vector<double> ca(L + 1), sa(L + 1), cb(L + 1), sb(L + 1);
  for (int m = 0; m <= L; ++m) {
    ca[m] = std::cos(m * a);
    sa[m] = std::sin(m * a);
    cb[m] = std::cos(m * b);
    sb[m] = std::sin(m * b);
  }
  a_.build(L, ca.data(), sa.data());
  b_.build(L, cb.data(), sb.data());
}

// Z(-pi/2) Y^-1 Z(b) Y Z(a + pi/2), degree by degree (rotations keep the degree).
void PivotRotation::to_frame2(const PivotTables& T, int Lmax, int Mmax, const double* in1, const double* in2,
                              double* out1, double* out2) const {
  PivotBuffers b;
  for (int l = 0; l <= Lmax; ++l) {
    const int mm = std::min({l, M_, Mmax});
    pivot_load(l, l, in1, in2, b.c, b.s);
    pivot_turn_forward(l, l, a_, b.c, b.s);
    pivot_forward(T, l, l, l, b.c, b.s, b.yc, b.ys);
    pivot_turn_forward(l, l, b_, b.yc, b.ys);
    pivot_backward(T, l, mm, b.yc, b.ys, b.c, b.s);
    pivot_turn_forward(l, mm, T.quarter(), b.c, b.s);
    pivot_store(l, mm, b.c, b.s, false, out1, out2);
  }
}

// The inverse, Z(a + pi/2)^-1 Y^-1 Z(b)^-1 Y Z(-pi/2)^-1, from frame orders <= min(M, Mmax), added to out
// (written with add = false).
void PivotRotation::from_frame2(const PivotTables& T, int Lmax, int Mmax, const double* in1, const double* in2,
                                double* out1, double* out2, bool add) const {
  PivotBuffers b;
  for (int l = 0; l <= Lmax; ++l) {
    const int mm = std::min({l, M_, Mmax});
    pivot_load(l, mm, in1, in2, b.c, b.s);
    pivot_turn_inverse(l, mm, T.quarter(), b.c, b.s);
    pivot_forward(T, l, mm, l, b.c, b.s, b.yc, b.ys);
    pivot_turn_inverse(l, l, b_, b.yc, b.ys);
    pivot_backward(T, l, l, b.yc, b.ys, b.c, b.s);
    pivot_turn_inverse(l, l, a_, b.c, b.s);
    pivot_store(l, l, b.c, b.s, add, out1, out2);
  }
}

}  // namespace agglo::es::sh
