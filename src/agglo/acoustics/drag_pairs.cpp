// The exact step of drag.hpp two samples at a time (SSE2 lanes): the arithmetic of
// Motion::advance_exact, operation for operation and in the same order, on a pair of samples, so that
// every result is bit for bit the reference's (tests/acoustics/test_motion_pairs.cpp). Lanes that take
// one of the rare branches (wave-phase cache refill, C_I > 1.001, h / tau_e <= 0.01, Re outside the
// polynomial's range, a wrap) are finished by the scalar code of the reference for that sample.
#include <cmath>
#include <cstdint>

#include "agglo/acoustics/drag.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace agglo::acoustics {

#if defined(__SSE2__)
namespace {
namespace pair_lanes {  // (named: unity batches join the anonymous namespaces of several files)
// Forced inline: the helpers are compiled inside each target clone of advance_exact_pairs.
#if defined(__GNUC__)
#define AGGLO_LANES inline __attribute__((always_inline))
#else
#define AGGLO_LANES inline
#endif
using v2 = __m128d;  // two doubles; + - * / are the IEEE operations of the scalar code per lane

AGGLO_LANES v2 set1(double a) { return _mm_set1_pd(a); }
AGGLO_LANES v2 load(const std::vector<double>& a, std::size_t i) { return _mm_loadu_pd(a.data() + i); }
AGGLO_LANES void store(std::vector<double>& a, std::size_t i, v2 v) { _mm_storeu_pd(a.data() + i, v); }
AGGLO_LANES double lane(v2 v, int l) { return l == 0 ? _mm_cvtsd_f64(v) : _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)); }
AGGLO_LANES v2 with_lane(v2 v, int l, double a) {
  return l == 0 ? _mm_move_sd(v, _mm_set_sd(a)) : _mm_unpacklo_pd(v, _mm_set_sd(a));
}
AGGLO_LANES v2 select(v2 mask, v2 a, v2 b) { return _mm_or_pd(_mm_and_pd(mask, a), _mm_andnot_pd(mask, b)); }
AGGLO_LANES v2 neg(v2 a) { return _mm_xor_pd(a, _mm_set1_pd(-0.0)); }  // -a (sign flip, as unary minus)

// gas.hpp's detail_log on two lanes (the exponent as an exact double through 2^52 + e).
AGGLO_LANES v2 log2l(v2 x) {
  const __m128i b = _mm_castpd_si128(x);
  const __m128i eb = _mm_and_si128(_mm_srli_epi64(b, 52), _mm_set1_epi64x(0x7ff));
  v2 e = _mm_sub_pd(_mm_castsi128_pd(_mm_or_si128(eb, _mm_set1_epi64x(0x4330000000000000LL))),
                    set1(4503599627370496.0)) - set1(1023.0);
  v2 m = _mm_castsi128_pd(_mm_or_si128(_mm_and_si128(b, _mm_set1_epi64x(0x000fffffffffffffLL)),
                                       _mm_set1_epi64x(0x3ff0000000000000LL)));
  const v2 big = _mm_cmpgt_pd(m, set1(1.4142135623730951));
  m = select(big, m * set1(0.5), m);
  e = select(big, e + set1(1.0), e);
  const v2 t = (m - set1(1.0)) / (m + set1(1.0)), t2 = t * t;
  const v2 ser =
      set1(1.0) + t2 * (set1(1.0 / 3) + t2 * (set1(1.0 / 5) + t2 * (set1(1.0 / 7) + t2 * (set1(1.0 / 9) +
      t2 * (set1(1.0 / 11) + t2 * set1(1.0 / 13))))));
  return e * set1(0.6931471805599453) + set1(2.0) * t * ser;
}

// gas.hpp's detail_exp_small on two lanes: 2^n from the low bits of y log2(e) + 1.5 2^52, which hold n.
AGGLO_LANES v2 exp2l(v2 y) {
  const v2 big = y * set1(1.4426950408889634) + set1(0x1.8p52);
  const v2 n = big - set1(0x1.8p52);
  const v2 r = (y - n * set1(0.6931471805599453)) - n * set1(2.3190468138462996e-17);
  const v2 p =
      set1(1.0) + r * (set1(1.0) + r * (set1(0.5) + r * (set1(1.0 / 6) + r * (set1(1.0 / 24) + r * (set1(1.0 / 120) +
      r * (set1(1.0 / 720) + r * (set1(1.0 / 5040) + r * (set1(1.0 / 40320) + r * (set1(1.0 / 362880) +
      r * (set1(1.0 / 3628800) + r * set1(1.0 / 39916800)))))))))));
  const __m128i sc = _mm_add_epi64(_mm_slli_epi64(_mm_castpd_si128(big), 52), _mm_set1_epi64x(1023LL << 52));
  return p * _mm_castsi128_pd(sc);
}

// Per-step constants of the pair step.
struct PairConst {
  v2 A, k, w, iw, h, swt, cwt, swh, cwh, G0, AiwN, Ak, hiw;
};

// wave_phase of drag.cpp on samples i, i + 1: s0, c0 = sin, cos(omega t - k x). A lane whose cache
// must be refilled is refilled by the scalar code first (its delta is then exactly 0, as there).
AGGLO_LANES void phase2(SampleSet& p, std::size_t i, const PairConst& c, v2& s0, v2& c0) {
  v2 dlt = c.k * (load(p.x, i) - load(p.x_ref, i));
  const v2 ok = _mm_cmple_pd(_mm_andnot_pd(set1(-0.0), dlt), set1(0.05));
  if (_mm_movemask_pd(ok) != 3)
    for (int l = 0; l < 2; ++l)
      if (!(std::abs(lane(dlt, l)) <= 0.05)) {
        const std::size_t j = i + static_cast<std::size_t>(l);
        const double k = lane(c.k, 0);
        p.x_ref[j] = p.x[j];
        p.skx[j] = std::sin(k * p.x[j]);
        p.ckx[j] = std::cos(k * p.x[j]);
        dlt = with_lane(dlt, l, 0.0);
      }
  const v2 d2 = dlt * dlt;
  const v2 sd = dlt * (set1(1.0) - d2 * set1(1.0 / 6) * (set1(1.0) - d2 * set1(1.0 / 20) * (set1(1.0) - d2 * set1(1.0 / 42))));
  const v2 cd = set1(1.0) - d2 * set1(0.5) *
                                (set1(1.0) - d2 * set1(1.0 / 12) *
                                                 (set1(1.0) - d2 * set1(1.0 / 30) * (set1(1.0) - d2 * set1(1.0 / 56))));
  const v2 sk = load(p.skx, i), ck = load(p.ckx, i);
  const v2 skx = sk * cd + ck * sd, ckx = ck * cd - sk * sd;
  s0 = c.swt * ckx - c.cwt * skx;
  c0 = c.cwt * ckx + c.swt * skx;
}

// Gas::inertia_correction_fast of two Reynolds numbers (lanes outside the polynomial's range by the scalar code).
AGGLO_LANES v2 ci2(v2 re) {
  const v2 inr = _mm_and_pd(_mm_cmpge_pd(re, set1(1e-30)), _mm_cmple_pd(re, set1(1e30)));  // also re > 0
  v2 ci = set1(1.0) + set1(0.15) * exp2l(set1(0.687) * log2l(select(inr, re, set1(1.0))));
  const int in = _mm_movemask_pd(inr);
  if (in != 3)
    for (int l = 0; l < 2; ++l)
      if (!((in >> l) & 1)) ci = with_lane(ci, l, Gas::inertia_correction_fast(lane(re, l)));
  return ci;
}

// Gas::reynolds(|(gas velocity - v)|, d) with the slip components sx, vy, vz.
AGGLO_LANES v2 reynolds2(const Gas& gas, SampleSet& p, std::size_t i, v2 sx, v2 vy, v2 vz) {
  const v2 slip = _mm_sqrt_pd(sx * sx + vy * vy + vz * vz);
  return slip * load(p.d, i) * set1(gas.density) / set1(gas.viscosity);
}

// midstep_tau of drag.cpp on two lanes (exp(-h/(2 te)) from libm per lane, as there).
AGGLO_LANES v2 midstep2(const Motion& m, SampleSet& p, std::size_t i, const PairConst& c, v2 s0, v2 c0, v2 te,
                   const Motion::StepTrig& tr) {
  const v2 xh = set1(0.5) * c.h / te;
  const v2 Eh = _mm_set_pd(std::exp(-lane(xh, 1)), std::exp(-lane(xh, 0)));
  const v2 q = c.w * te, D = set1(1.0) + q * q;
  const v2 sh = s0 * set1(tr.cwh2) + c0 * set1(tr.swh2), ch = c0 * set1(tr.cwh2) - s0 * set1(tr.swh2);
  const v2 vxh = c.A * (sh - q * ch) / D + (load(p.vx, i) - c.A * (s0 - q * c0) / D) * Eh;
  const v2 sxh = c.A * sh - vxh;
  const v2 vt = load(p.acc_z, i) * te, vz = load(p.vz, i);
  const v2 vyh = load(p.vy, i) * Eh, vzh = vt + (vz - vt) * Eh;
  return load(p.tau, i) / ci2(reynolds2(m.gas, p, i, sxh, vyh, vzh));
}

// tau_e = tau / C_I at the start-of-step slip (start_reynolds, Gas::inertia_correction_fast), with the
// mid-step C_I (midstep_tau) of drag.cpp in lanes where C_I > 1.001.
AGGLO_LANES v2 tau_e2(const Motion& m, SampleSet& p, std::size_t i, const PairConst& c, v2 s0, v2 c0,
                 const Motion::StepTrig& tr) {
  const v2 ci = ci2(reynolds2(m.gas, p, i, c.A * s0 - load(p.vx, i), load(p.vy, i), load(p.vz, i)));
  const v2 te = load(p.tau, i) / ci;
  const v2 mid = _mm_cmpgt_pd(ci, set1(1.001));
  if (_mm_movemask_pd(mid) == 0) return te;
  return select(mid, midstep2(m, p, i, c, s0, c0, te, tr), te);
}

// decay of drag.cpp: E = exp(-h/te) and omE = 1 - E, E = 0 beyond h/te = 40, expm1 at or below 0.01.
AGGLO_LANES void decay2(v2 x, v2& E, v2& omE) {
  const v2 far = _mm_cmpgt_pd(x, set1(40.0));
  if (_mm_movemask_pd(far) == 3) {  // both beyond 40 (most fine solids at the default step)
    E = set1(0.0);
    omE = set1(1.0);
    return;
  }
  const v2 Ep = exp2l(neg(_mm_min_pd(x, set1(700.0))));
  E = select(far, set1(0.0), Ep);
  omE = select(far, set1(1.0), set1(1.0) - Ep);
  const int small = _mm_movemask_pd(_mm_cmpgt_pd(x, set1(0.01)));
  if (small != 3)
    for (int l = 0; l < 2; ++l)
      if (!((small >> l) & 1)) {
        const double o = -std::expm1(-lane(x, l));
        omE = with_lane(omE, l, o);
        E = with_lane(E, l, 1.0 - o);
      }
}

// drift_correction of drag.cpp on two lanes (same expressions; G0 = 0.5 A A k / omega, AiwN = A / omega,
// Ak = A k, hiw = 0.5 / omega).
AGGLO_LANES void drift2(const PairConst& c, v2 te, v2 iD, v2 E, v2 omE, v2 s0, v2 c0, v2 s1, v2 c1, v2 dv, v2& dx,
                   v2& dvx) {
  const v2 q = c.w * te;
  const v2 G = c.G0 * iD;
  const v2 X0 = neg(c.AiwN * iD) * (c0 + q * s0);
  const v2 teomE = te * omE;
  v2 v1 = G * omE;
  v2 x1 = G * (c.h - teomE);
  const v2 GD2 = G / (set1(1.0) + set1(4.0) * q * q);
  const v2 al = GD2 * (set1(1.0) - set1(2.0) * q * q), be = set1(3.0) * q * GD2;
  const v2 C20 = c0 * c0 - s0 * s0, S20 = set1(2.0) * s0 * c0, C21 = c1 * c1 - s1 * s1, S21 = set1(2.0) * s1 * c1;
  const v2 P20 = al * C20 + be * S20;
  v1 = v1 + ((al * C21 + be * S21) - P20 * E);
  x1 = x1 + ((al * (S21 - S20) - be * (C21 - C20)) * c.hiw - P20 * teomE);
  const v2 HD = c.Ak * (X0 - dv * te) * iD;
  const v2 ab = HD, bb = HD * q;
  const v2 P10 = ab * c0 + bb * s0;
  v1 = v1 + ((ab * c1 + bb * s1) - P10 * E);
  x1 = x1 + ((ab * (s1 - s0) - bb * (c1 - c0)) * c.iw - P10 * teomE);
  const v2 Kq = c.Ak * dv * c.iw;
  v1 = v1 + Kq * E * (s1 - s0);
  x1 = x1 + Kq * te * (((s0 - E * s1) - q * (E * c1 - c0)) * iD - s0 * omE);
  dx = dx + x1;
  dvx = dvx + v1;
}

// exact_update and transverse_step of drag.cpp (sound on) on samples i, i + 1; wraps by the scalar code.
AGGLO_LANES void update2(const Motion& m, SampleSet& p, std::size_t i, const PairConst& c, v2 te, v2 E, v2 omE, v2 s0,
                    v2 c0) {
  const v2 q = c.w * te, iD = set1(1.0) / (set1(1.0) + q * q), AD = c.A * iD;
  const v2 s1 = s0 * c.cwh + c0 * c.swh, c1 = c0 * c.cwh - s0 * c.swh;
  const v2 vs0 = AD * (s0 - q * c0), vs1 = AD * (s1 - q * c1);
  const v2 dX = neg(AD) * ((c1 - c0) + q * (s1 - s0)) * c.iw;
  const v2 dv = load(p.vx, i) - vs0;
  v2 dx = dX + dv * te * omE, vx = vs1 + dv * E;
  drift2(c, te, iD, E, omE, s0, c0, s1, c1, dv, dx, vx);
  const v2 x = load(p.x, i) + dx;
  store(p.vx, i, vx);
  const v2 vy = load(p.vy, i), vz = load(p.vz, i), vt = load(p.acc_z, i) * te;
  const v2 y = load(p.y, i) + vy * te * omE;
  store(p.vy, i, vy * E);
  const v2 dz = vz - vt;
  const v2 z = load(p.z, i) + (vt * c.h + dz * te * omE);
  store(p.vz, i, vt + dz * E);
  store(p.x, i, x);
  store(p.y, i, y);
  store(p.z, i, z);
  const v2 zero = set1(0.0);
  const v2 out = _mm_or_pd(_mm_or_pd(_mm_or_pd(_mm_cmplt_pd(x, zero), _mm_cmpge_pd(x, set1(m.domain.L[0]))),
                                     _mm_or_pd(_mm_cmplt_pd(y, zero), _mm_cmpge_pd(y, set1(m.domain.L[1])))),
                           _mm_or_pd(_mm_cmplt_pd(z, zero), _mm_cmpge_pd(z, set1(m.domain.L[2]))));
  const int wr = _mm_movemask_pd(out);
  if (wr & 1) m.wrap(p, i);
  if (wr & 2) m.wrap(p, i + 1);
}
#undef AGGLO_LANES
}  // namespace pair_lanes
}  // namespace

// With GCC on x86-64 the step is also compiled for AVX2 (three-operand VEX encoding, the same IEEE
// operations: no FMA, so the same bits) and the loader picks that clone where the processor has it.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(AGGLO_NO_TARGET_CLONES)
__attribute__((target_clones("avx2", "default")))
#endif
void Motion::advance_exact_pairs(SampleSet& p, std::size_t begin, std::size_t end, const StepTrig& tr,
                                 double h) const {
  const double A = sound.u_amp;
  if (!(A > 0.0) || !inertia_correction) {  // not the default: the scalar block step
    advance_exact_block(p, begin, end, tr, h);
    return;
  }
  using namespace pair_lanes;
  const double k = sound.wavenumber, w = sound.omega, iw = tr.inv_omega;
  const PairConst c{set1(A),      set1(k),      set1(w),      set1(iw),
                    set1(h),      set1(tr.swt), set1(tr.cwt), set1(tr.swh),
                    set1(tr.cwh), set1(0.5 * A * A * k * iw), set1(A * iw), set1(A * k), set1(0.5 * iw)};
  std::size_t i = begin;
  for (; i + 1 < end; i += 2) {
    v2 s0, c0;
    phase2(p, i, c, s0, c0);
    const v2 te = tau_e2(*this, p, i, c, s0, c0, tr);
    v2 E, omE;
    decay2(c.h / te, E, omE);
    update2(*this, p, i, c, te, E, omE, s0, c0);
  }
  if (i < end) advance_exact(p, i, tr, h);
}
#else
void Motion::advance_exact_pairs(SampleSet& p, std::size_t begin, std::size_t end, const StepTrig& tr,
                                 double h) const {
  advance_exact_block(p, begin, end, tr, h);
}
#endif

}  // namespace agglo::acoustics
