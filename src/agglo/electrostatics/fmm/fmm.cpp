#include "agglo/electrostatics/fmm/fmm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "agglo/electrostatics/fmm/solid_harmonics.hpp"

namespace agglo::es::fmm {

namespace {

// Plain complex product (std::complex operator* goes through __muldc3 without -ffast-math).
inline cplx mul(const cplx& a, const cplx& b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

void check_options(const FmmOptions& o) {
  if (o.order < 1 || o.order > 40) throw std::invalid_argument("fmm: order must be in [1, 40]");
  if (o.leaf_size < 1) throw std::invalid_argument("fmm: leaf_size must be >= 1");
  if (!(o.theta > 0.0 && o.theta < 1.0)) throw std::invalid_argument("fmm: theta must be in (0, 1)");
}

}  // namespace

int order_for_tolerance(double tol) {
  // Calibrated with theta = 0.4, leaf 64 (docs/bem_fmm.md): the relative 2-norm field error on
  // points on touching sphere surfaces (the worse of surface and volume sets) is below
  // kFmmErrorPrefactor * kFmmErrorRatio^p.
  tol = std::clamp(tol, 1e-15, 0.1);
  const int p = static_cast<int>(std::ceil(std::log(tol / kFmmErrorPrefactor) / std::log(kFmmErrorRatio)));
  return std::clamp(p, 2, 30);
}

LaplaceFmm::LaplaceFmm(std::span<const Vec3> points, const FmmOptions& opt)
    : opt_(opt), same_(true), src_(points, opt.leaf_size) {
  check_options(opt);
  lists_ = build_interaction_lists(src_, src_, opt.theta);
}

LaplaceFmm::LaplaceFmm(std::span<const Vec3> sources, std::span<const Vec3> targets, const FmmOptions& opt)
    : opt_(opt), same_(false), src_(sources, opt.leaf_size), tgt_(targets, opt.leaf_size) {
  check_options(opt);
  lists_ = build_interaction_lists(tgt_, src_, opt.theta);
}

void LaplaceFmm::evaluate(std::span<const double> charges, std::vector<double>* potential,
                          std::vector<Vec3>* field) const {
  const Octree& S = src_;
  const Octree& T = tgt();
  const int p = opt_.order;
  const int ts = tri_size(p);
  const int fs = (p + 1) * (p + 1);
  const std::size_t ns = S.order.size(), nt = T.order.size();
  if (charges.size() != ns) throw std::invalid_argument("fmm: charges size differs from sources");
  std::vector<double> phi(nt, 0.0), ex(nt, 0.0), ey(nt, 0.0), ez(nt, 0.0);
  if (ns == 0 || nt == 0) {
    if (potential) *potential = phi;
    if (field) field->assign(nt, Vec3{});
    return;
  }
  std::vector<double> q(ns);
  for (std::size_t k = 0; k < ns; ++k) q[k] = charges[S.order[k]];

  // ---- upward pass: P2M at leaves, M2M to parents (deepest level first) ----
  const std::size_t nsc = S.cells.size();
  std::vector<cplx> M(nsc * ts, cplx(0.0, 0.0));
  for (int lev = S.levels() - 1; lev >= 0; --lev) {
#pragma omp parallel
    {
      std::vector<cplx> R(ts);
#pragma omp for schedule(dynamic, 4)
      for (int c = S.level_begin[lev]; c < S.level_begin[lev + 1]; ++c) {
        const Cell& cell = S.cells[c];
        cplx* Mc = &M[c * ts];
        if (cell.leaf()) {
          for (int k = cell.begin; k < cell.end; ++k) {
            regular_harmonics(Vec3{S.sorted.x[k], S.sorted.y[k], S.sorted.z[k]} - cell.center, p, R.data());
            for (int i = 0; i < ts; ++i) Mc[i] += q[k] * std::conj(R[i]);
          }
        } else {
          for (int ch = cell.child; ch < cell.child + cell.nchild; ++ch) {
            const cplx* Mch = &M[ch * ts];
            regular_harmonics(S.cells[ch].center - cell.center, p, R.data());
            for (int n = 0; n <= p; ++n)
              for (int m = 0; m <= n; ++m) {
                cplx acc(0.0, 0.0);
                for (int k = 0; k <= n; ++k)
                  for (int l = std::max(-k, m - (n - k)); l <= std::min(k, m + (n - k)); ++l)
                    acc += mul(std::conj(coeff(R.data(), k, l)), coeff(Mch, n - k, m - l));
                Mc[tri(n, m)] += acc;
              }
          }
        }
      }
    }
  }
  // Full (all m) split real/imag multipoles for the M2L inner loop.
  std::vector<double> Mre(nsc * fs), Mim(nsc * fs);
#pragma omp parallel for schedule(static)
  for (std::size_t c = 0; c < nsc; ++c)
    for (int n = 0; n <= p; ++n)
      for (int m = -n; m <= n; ++m) {
        const cplx v = coeff(&M[c * ts], n, m);
        Mre[c * fs + n * n + n + m] = v.real();
        Mim[c * fs + n * n + n + m] = v.imag();
      }

  // ---- M2L into target cells ----
  const std::size_t ntc = T.cells.size();
  std::vector<cplx> L(ntc * ts, cplx(0.0, 0.0));
#pragma omp parallel
  {
    std::vector<cplx> I(ts);
    std::vector<double> Ire(fs), Iim(fs);
#pragma omp for schedule(dynamic, 2)
    for (std::size_t c = 0; c < ntc; ++c) {
      const auto& list = lists_.m2l[c];
      if (list.empty()) continue;
      cplx* Lc = &L[c * ts];
      for (int b : list) {
        irregular_harmonics(T.cells[c].center - S.cells[b].center, p, I.data());
        for (int n = 0; n <= p; ++n)
          for (int m = -n; m <= n; ++m) {
            const cplx v = coeff(I.data(), n, m);
            Ire[n * n + n + m] = v.real();
            Iim[n * n + n + m] = v.imag();
          }
        const double* mr0 = &Mre[b * fs];
        const double* mi0 = &Mim[b * fs];
        for (int j = 0; j <= p; ++j)
          for (int s = 0; s <= j; ++s) {
            double re = 0.0, im = 0.0;
            for (int n = 0; n <= p - j; ++n) {
              const double* mr = mr0 + n * n + n;
              const double* mi = mi0 + n * n + n;
              const int o = (n + j) * (n + j) + (n + j) - s;
              const double* ir = &Ire[o];
              const double* ii = &Iim[o];
#pragma omp simd reduction(+ : re, im)
              for (int m = -n; m <= n; ++m) {
                re += mr[m] * ir[m] - mi[m] * ii[m];
                im += mr[m] * ii[m] + mi[m] * ir[m];
              }
            }
            const double sign = ((j + s) & 1) ? -1.0 : 1.0;
            Lc[tri(j, s)] += cplx(sign * re, sign * im);
          }
      }
    }
  }

  // ---- downward pass: L2L parent -> child ----
  for (int lev = 1; lev < T.levels(); ++lev) {
#pragma omp parallel
    {
      std::vector<cplx> R(ts);
#pragma omp for schedule(dynamic, 4)
      for (int c = T.level_begin[lev]; c < T.level_begin[lev + 1]; ++c) {
        const Cell& cell = T.cells[c];
        const cplx* Lp = &L[cell.parent * ts];
        cplx* Lc = &L[c * ts];
        regular_harmonics(cell.center - T.cells[cell.parent].center, p, R.data());
        for (int j = 0; j <= p; ++j)
          for (int s = 0; s <= j; ++s) {
            cplx acc(0.0, 0.0);
            for (int k = 0; k <= p - j; ++k)
              for (int l = -k; l <= k; ++l) acc += mul(coeff(R.data(), k, l), coeff(Lp, j + k, s + l));
            Lc[tri(j, s)] += acc;
          }
      }
    }
  }

  // ---- leaves: L2P and P2P ----
  const Points& tp = T.sorted;
  const Points& sp = S.sorted;
  const bool want_field = field != nullptr;
#pragma omp parallel
  {
    std::vector<cplx> R(ts);
#pragma omp for schedule(dynamic, 2)
    for (std::size_t c = 0; c < ntc; ++c) {
      const Cell& cell = T.cells[c];
      if (!cell.leaf()) continue;
      const cplx* Lc = &L[c * ts];
      for (int i = cell.begin; i < cell.end; ++i) {
        regular_harmonics(Vec3{tp.x[i], tp.y[i], tp.z[i]} - cell.center, p, R.data());
        double pot = 0.0;
        for (int n = 0; n <= p; ++n) {
          pot += mul(Lc[tri(n, 0)], R[tri(n, 0)]).real();
          for (int m = 1; m <= n; ++m) pot += 2.0 * mul(Lc[tri(n, m)], R[tri(n, m)]).real();
        }
        phi[i] += pot;
        if (want_field) {
          // Degree-1 coefficients of the local expansion shifted to the target.
          cplx l10(0.0, 0.0), l11(0.0, 0.0);
          for (int k = 0; k < p; ++k)
            for (int l = -k; l <= k; ++l) {
              const cplx r = coeff(R.data(), k, l);
              l10 += mul(r, coeff(Lc, 1 + k, l));
              l11 += mul(r, coeff(Lc, 1 + k, 1 + l));
            }
          // grad phi = (-Re l11, Im l11, l10); E = -grad phi
          ex[i] += l11.real();
          ey[i] -= l11.imag();
          ez[i] -= l10.real();
        }
      }
      const int nti = cell.end - cell.begin;
      for (int b : lists_.p2p[c]) {
        const Cell& sc = S.cells[b];
        p2p_accumulate(&tp.x[cell.begin], &tp.y[cell.begin], &tp.z[cell.begin], nti, &sp.x[sc.begin],
                       &sp.y[sc.begin], &sp.z[sc.begin], &q[sc.begin], sc.end - sc.begin, &phi[cell.begin],
                       want_field ? &ex[cell.begin] : nullptr, &ey[cell.begin], &ez[cell.begin]);
      }
    }
  }

  // ---- back to input order ----
  if (potential) {
    potential->assign(nt, 0.0);
    for (std::size_t k = 0; k < nt; ++k) (*potential)[T.order[k]] = phi[k];
  }
  if (field) {
    field->assign(nt, Vec3{});
    for (std::size_t k = 0; k < nt; ++k) (*field)[T.order[k]] = {ex[k], ey[k], ez[k]};
  }
}

}  // namespace agglo::es::fmm
