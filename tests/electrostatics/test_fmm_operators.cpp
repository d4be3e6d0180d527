// Each FMM operator of fmm/operators.hpp on its own against direct sums.
// Tolerances are the truncation-error bounds of an order-p expansion (Q = sum |q|):
//   multipole about c, sources within a, evaluated at distance r > a:
//     |phi error| <= Q (a/r)^(p+1) / (r - a)
//   local expansion of sources at distance >= b from c, evaluated within r < b:
//     |phi error| <= Q (r/b)^(p+1) / (b - r),   |E error| <= Q sum_{k>p} (k+1) r^(k-1) / b^(k+1)
//   M2L truncated at n + j <= p (= degree p in w = (y - c_S) - (x - c_T), |w| <= rho = a + r_T),
//   centres D apart: the same two bounds with r -> rho, b -> D.
// (From 1/|D - w| = sum_k |w|^k P_k(cos g) / |D|^(k+1), |P_k| <= 1, and for the field
// |grad(|w|^k P_k)| <= sqrt(k(k+1)) |w|^(k-1).) M2M and L2L re-centre without truncation: they
// must agree with the unshifted expansion to rounding, allowed as 1e-12 of the term scale.
// Every check adds that rounding allowance 1e-12 Q / (distance) to the truncation bound.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "agglo/electrostatics/fmm/direct.hpp"
#include "agglo/electrostatics/fmm/operators.hpp"
#include "agglo/electrostatics/fmm/solid_harmonics.hpp"

using namespace agglo;
using namespace agglo::es::fmm;

namespace {

constexpr double kRound = 1e-12;  // rounding allowance, relative to the scale of the terms

struct Cloud {
  std::vector<Vec3> x;
  std::vector<double> q;
  double abs_sum() const {
    double s = 0.0;
    for (double v : q) s += std::abs(v);
    return s;
  }
};

// n points uniform in the ball of radius a about c, charges uniform in [-1, 1].
Cloud ball(const Vec3& c, double a, int n, unsigned seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Cloud cl;
  while (static_cast<int>(cl.x.size()) < n) {
    const Vec3 d{u(g), u(g), u(g)};
    if (norm(d) > 1.0) continue;
    cl.x.push_back(c + a * d);
    cl.q.push_back(u(g));
  }
  return cl;
}

double max_distance(const std::vector<Vec3>& x, const Vec3& c) {
  double r = 0.0;
  for (const auto& p : x) r = std::max(r, norm(p - c));
  return r;
}

// Potential of a multipole expansion about the origin at offset x: sum_{n, |m|<=n} M_n^m I_n^m(x).
double multipole_potential(const std::vector<cplx>& M, const Vec3& x, int p) {
  std::vector<cplx> I(tri_size(p));
  irregular_harmonics(x, p, I.data());
  double phi = 0.0;
  for (int n = 0; n <= p; ++n) {
    phi += (M[tri(n, 0)] * I[tri(n, 0)]).real();
    for (int m = 1; m <= n; ++m) phi += 2.0 * (M[tri(n, m)] * I[tri(n, m)]).real();
  }
  return phi;
}

// Direct local expansion about c of far sources: L_n^m = sum_j q_j conj(I_n^m(y_j - c)), from
// 1/|x - y| = sum conj(R_n^m(x)) I_n^m(y) for |x| < |y| and conj(R_n^m) = (-1)^m R_n^{-m}.
std::vector<cplx> direct_local(const Cloud& s, const Vec3& c, int p) {
  std::vector<cplx> L(tri_size(p), cplx(0.0, 0.0)), I(tri_size(p));
  for (std::size_t j = 0; j < s.x.size(); ++j) {
    irregular_harmonics(s.x[j] - c, p, I.data());
    for (int i = 0; i < tri_size(p); ++i) L[i] += s.q[j] * std::conj(I[i]);
  }
  return L;
}

// Reference potential and field (long double) at x, skipping coincident points.
void direct(const Cloud& s, const Vec3& x, double& phi, Vec3& e) {
  long double p = 0, ex = 0, ey = 0, ez = 0;
  for (std::size_t j = 0; j < s.x.size(); ++j) {
    const long double dx = x.x - s.x[j].x, dy = x.y - s.x[j].y, dz = x.z - s.x[j].z;
    const long double r2 = dx * dx + dy * dy + dz * dz;
    if (r2 == 0) continue;
    const long double r = std::sqrt(r2), w = s.q[j] / (r2 * r);
    p += s.q[j] / r;
    ex += w * dx;
    ey += w * dy;
    ez += w * dz;
  }
  phi = static_cast<double>(p);
  e = {static_cast<double>(ex), static_cast<double>(ey), static_cast<double>(ez)};
}

double potential_bound(double Q, double near, double far, int p) {
  return Q * std::pow(near / far, p + 1) / (far - near);
}

// Q sum_{k>p} (k+1) near^(k-1) / far^(k+1) = Q / far^2 sum_{k>p} (k+1) t^(k-1), t = near / far < 1.
double field_bound(double Q, double near, double far, int p) {
  const double t = near / far;
  double s = 0.0, tk = std::pow(t, p);  // t^(k-1) for k = p + 1
  for (int k = p + 1; (k + 1) * tk > 1e-20 * s || k < p + 10; ++k, tk *= t) s += (k + 1) * tk;
  return Q * s / (far * far);
}

// The local expansion L about c (order p) at the target points, against the direct sums of s:
// potential and field within the given bounds.
void expect_local_matches(const std::vector<cplx>& L, const Vec3& c, const std::vector<Vec3>& targets, int p,
                          const Cloud& s, double phi_tol, double e_tol) {
  OperatorScratch scratch(p);
  for (const auto& x : targets) {
    Vec3 e;
    const double phi = l2p(L.data(), x - c, p, &e, scratch);
    double phi_ref;
    Vec3 e_ref;
    direct(s, x, phi_ref, e_ref);
    EXPECT_LE(std::abs(phi - phi_ref), phi_tol) << "p " << p;
    EXPECT_LE(norm(e - e_ref), e_tol) << "p " << p;
    EXPECT_EQ(l2p(L.data(), x - c, p, nullptr, scratch), phi);
  }
}

// Local expansion about ct of the sources s: P2M about cs, then M2L.
std::vector<cplx> local_by_m2l(const Cloud& s, const Vec3& cs, const Vec3& ct, int p) {
  OperatorScratch scratch(p);
  std::vector<cplx> M(tri_size(p), cplx(0.0, 0.0)), L(tri_size(p), cplx(0.0, 0.0));
  p2m(Points(s.x), 0, static_cast<int>(s.x.size()), s.q.data(), cs, p, M.data(), scratch);
  std::vector<double> re((p + 1) * (p + 1)), im((p + 1) * (p + 1));
  split_multipole(M.data(), p, re.data(), im.data());
  m2l(re.data(), im.data(), ct - cs, p, L.data(), scratch);
  return L;
}

}  // namespace

TEST(FmmOperators, P2MAtFarPointsMatchesDirectPotential) {
  const Vec3 c{0.3, -0.2, 0.1};
  const Cloud s = ball(c, 1.0, 200, 1);
  const double Q = s.abs_sum(), a = max_distance(s.x, c);
  const Points pts(s.x);
  for (int p : {2, 6, 12}) {
    OperatorScratch scratch(p);
    std::vector<cplx> M(tri_size(p), cplx(0.0, 0.0));
    p2m(pts, 0, static_cast<int>(s.x.size()), s.q.data(), c, p, M.data(), scratch);
    for (const Vec3& dir : {Vec3{1, 0, 0}, Vec3{0.6, -0.8, 0}, Vec3{0.2, 0.3, -0.93}}) {
      for (double r : {2.0, 3.5}) {
        const Vec3 x = c + (r / norm(dir)) * dir;
        double phi_ref;
        Vec3 e_ref;
        direct(s, x, phi_ref, e_ref);
        EXPECT_LE(std::abs(multipole_potential(M, x - c, p) - phi_ref),
                  potential_bound(Q, a, r, p) + kRound * Q / (r - a))
            << "p " << p << " r " << r;
      }
    }
  }
}

TEST(FmmOperators, M2MEqualsP2MAboutTheParentCentre) {
  const Vec3 parent{0.0, 0.0, 0.0};
  const std::vector<Vec3> centres{{0.5, 0.5, 0.5}, {-0.5, 0.5, -0.5}, {0.5, -0.5, -0.5}};
  Cloud all;
  const int p = 10;
  std::vector<cplx> shifted(tri_size(p), cplx(0.0, 0.0));
  OperatorScratch scratch(p);
  for (std::size_t c = 0; c < centres.size(); ++c) {
    const Cloud s = ball(centres[c], 0.5, 60, 10 + static_cast<unsigned>(c));
    std::vector<cplx> Mc(tri_size(p), cplx(0.0, 0.0));
    p2m(Points(s.x), 0, static_cast<int>(s.x.size()), s.q.data(), centres[c], p, Mc.data(), scratch);
    m2m(Mc.data(), centres[c] - parent, p, shifted.data(), scratch);
    all.x.insert(all.x.end(), s.x.begin(), s.x.end());
    all.q.insert(all.q.end(), s.q.begin(), s.q.end());
  }
  std::vector<cplx> Mp(tri_size(p), cplx(0.0, 0.0));
  p2m(Points(all.x), 0, static_cast<int>(all.x.size()), all.q.data(), parent, p, Mp.data(), scratch);
  // |R_n^m(y)| <= |y|^n: coefficients of degree n are at most Q (|shift| + a_child)^n.
  const double Q = all.abs_sum(), rho = std::sqrt(0.75) + 0.5;
  for (int n = 0; n <= p; ++n)
    for (int m = 0; m <= n; ++m)
      EXPECT_LE(std::abs(shifted[tri(n, m)] - Mp[tri(n, m)]), kRound * Q * std::pow(rho, n)) << n << "," << m;
  // and the shifted expansion's far field obeys the bound about the parent centre
  const double a = max_distance(all.x, parent);
  for (double r : {2.5, 4.0}) {
    const Vec3 x{0.0, r, 0.0};
    double phi_ref;
    Vec3 e_ref;
    direct(all, x, phi_ref, e_ref);
    EXPECT_LE(std::abs(multipole_potential(shifted, x, p) - phi_ref), potential_bound(Q, a, r, p) + kRound * Q / (r - a));
  }
}

TEST(FmmOperators, L2PPotentialAndFieldOfADirectLocalExpansion) {
  const Vec3 c{0.1, 0.2, -0.3};
  const Cloud s = ball(c + Vec3{0.0, 0.0, 4.0}, 1.0, 150, 3);
  const Cloud t = ball(c, 1.0, 40, 4);
  const double Q = s.abs_sum();
  double b = 1e300;
  for (const auto& y : s.x) b = std::min(b, norm(y - c));
  const double r = max_distance(t.x, c);
  for (int p : {2, 6, 12}) {
    const auto L = direct_local(s, c, p);
    expect_local_matches(L, c, t.x, p, s, potential_bound(Q, r, b, p) + kRound * Q / (b - r),
                         field_bound(Q, r, b, p) + kRound * Q / ((b - r) * (b - r)));
  }
}

TEST(FmmOperators, M2LThenL2PMatchesDirectSums) {
  const Vec3 cs{0.0, 0.0, 0.0}, ct{1.5, -2.0, 2.5};
  const Cloud s = ball(cs, 1.0, 150, 5);
  const Cloud t = ball(ct, 0.8, 40, 6);
  const double Q = s.abs_sum(), D = norm(ct - cs);
  const double rho = max_distance(s.x, cs) + max_distance(t.x, ct);
  for (int p : {2, 6, 12}) {
    const auto L = local_by_m2l(s, cs, ct, p);
    expect_local_matches(L, ct, t.x, p, s, potential_bound(Q, rho, D, p) + kRound * Q / (D - rho),
                         field_bound(Q, rho, D, p) + kRound * Q / ((D - rho) * (D - rho)));
  }
}

TEST(FmmOperators, L2LReproducesTheParentExpansion) {
  const Vec3 cs{0.0, 0.0, 0.0}, parent{0.5, 3.0, 2.0}, child{0.9, 2.7, 2.3};
  const Cloud s = ball(cs, 1.0, 150, 7);
  const Cloud t = ball(child, 0.4, 30, 8);
  const double Q = s.abs_sum(), D = norm(parent - cs);
  const double rho = max_distance(s.x, cs) + max_distance(t.x, parent);
  for (int p : {2, 6, 12}) {
    OperatorScratch scratch(p);
    const auto Lp = local_by_m2l(s, cs, parent, p);
    std::vector<cplx> Lc(tri_size(p), cplx(0.0, 0.0));
    l2l(Lp.data(), child - parent, p, Lc.data(), scratch);
    // The same degree-p polynomial about another centre: equal to rounding at every target.
    const double scale = Q / (D - rho);
    for (const auto& x : t.x) {
      Vec3 ep, ec;
      const double pp = l2p(Lp.data(), x - parent, p, &ep, scratch);
      const double pc = l2p(Lc.data(), x - child, p, &ec, scratch);
      EXPECT_LE(std::abs(pc - pp), kRound * scale) << "p " << p;
      EXPECT_LE(norm(ec - ep), kRound * scale / (D - rho)) << "p " << p;
    }
    // hence the child expansion meets the M2L bound of the parent's targets
    expect_local_matches(Lc, child, t.x, p, s, potential_bound(Q, rho, D, p) + kRound * scale,
                         field_bound(Q, rho, D, p) + kRound * scale / (D - rho));
  }
}

TEST(FmmOperators, P2PMatchesDirectSumOnSubranges) {
  Cloud s = ball({0, 0, 0}, 1.0, 90, 9);
  Cloud t = ball({0.5, 0, 0}, 1.0, 50, 10);
  t.x[20] = s.x[40];  // a coincident pair: skipped
  const Points S(s.x), T(t.x);
  const int tb = 10, te = 45, sb = 30, se = 80;
  std::vector<double> phi(t.x.size(), 0.0), ex(phi), ey(phi), ez(phi), phi_only(phi);
  p2p(T, tb, te, S, sb, se, s.q.data(), phi.data(), ex.data(), ey.data(), ez.data());
  p2p(T, tb, te, S, sb, se, s.q.data(), phi_only.data(), nullptr, nullptr, nullptr);
  const Cloud sub{std::vector<Vec3>(s.x.begin() + sb, s.x.begin() + se),
                  std::vector<double>(s.q.begin() + sb, s.q.begin() + se)};
  std::vector<double> phi_d;
  std::vector<Vec3> e_d;
  direct_sum(std::vector<Vec3>(t.x.begin() + tb, t.x.begin() + te), sub.x, sub.q, &phi_d, &e_d);
  for (int i = 0; i < static_cast<int>(t.x.size()); ++i) {
    if (i < tb || i >= te) {
      EXPECT_EQ(phi[i], 0.0);
      EXPECT_EQ(ex[i], 0.0);
      continue;
    }
    double phi_ref;
    Vec3 e_ref;
    direct(sub, t.x[i], phi_ref, e_ref);
    const double scale = sub.abs_sum() / 1e-3;  // no pair closer than 1e-3 except the coincident one
    EXPECT_LE(std::abs(phi[i] - phi_ref), 1e-13 * scale) << i;
    EXPECT_LE(norm(Vec3{ex[i], ey[i], ez[i]} - e_ref), 1e-13 * scale / 1e-3) << i;
    EXPECT_EQ(phi_only[i], phi[i]);
    EXPECT_NEAR(phi[i], phi_d[i - tb], 1e-13 * scale);
    EXPECT_LE(norm(Vec3{ex[i], ey[i], ez[i]} - e_d[i - tb]), 1e-13 * scale / 1e-3);
  }
  for (int i = 0; i < static_cast<int>(t.x.size()); ++i)
    for (int j = sb; j < se; ++j)
      if (!(i == 20 && j == 40)) {
        ASSERT_GT(norm(t.x[i] - s.x[j]), 1e-3) << i << "," << j;
      }
}
