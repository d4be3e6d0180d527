#pragma once
// Rotation of spherical-harmonic coefficients into a pair frame through two fixed quarter turns
// ("pivot" rotation; the factorisation of Gumerov & Duraiswami, Fast Multipole Methods for the
// Helmholtz Equation in Three Dimensions, 2004, sec. 3.3, and Pinchon & Hoggan 2007, J. Phys. A 40,
// 1597): the frame map of rotation.hpp, Q = R_y(-b) R_z(-a) (Q e = z), is
//   Q = R_z(pi/2) R_y(pi/2) R_z(-b) R_y(-pi/2) R_z(-(a + pi/2)),
// from R_y(beta) = R_z(pi/2) R_x(beta) R_z(-pi/2) and R_x(beta) = R_y(pi/2) R_z(beta) R_y(-pi/2).
// The coefficient maps compose in the same order (T[Q2 Q1] = T[Q2] T[Q1] in the convention of
// FrameRotation::to_frame), so
//   to_frame = Z(-pi/2) Y^-1 Z(b) Y Z(a + pi/2),   Y = T[R_y(-pi/2)],
// with Z(phi) the z rotation of FrameRotation::to_frame by phi (O(l) per degree) and Y the blocks of a
// FrameRotation built for e = x, kept by parity (PivotTables: one set per solver degree, shared by every pair).
// A pair stores only cos/sin of m (a + pi/2) and m b (O(L) numbers instead of the O(L^2 M) blocks of
// FrameRotation); the work per degree l and vector is about l^2 / 2 + l^2 / 2 for the full quarter turn
// plus (M l) / 2 + (M l) / 2 for the one cut to frame orders <= M (half the blocks vanish, see
// PivotTables), about 1.4 times the products of stored blocks at l = 47, M = 25, but from tables that
// stay in cache instead of a stream from memory (0.45 MB of blocks per touching pair at L = 47). Same results as FrameRotation to rounding
// (tests/electrostatics/test_pivot_rotation.cpp).
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/electrostatics/spectral/rotation.hpp"

namespace agglo::es::sh {

// cos(m phi), sin(m phi), m = 0..L (given as cs, sn), in the order the z rotation of a degree reads them (its buffers hold
// the orders of one parity in a run, each order's two vectors side by side): the even orders m at [m, m + 1],
// the odd ones at [odd + m - 1, odd + m], each number twice (one copy per vector), so that the rotation of
// a run is an element-wise pass over contiguous numbers.
struct TurnTable {
  std::vector<double> c, s;
  int odd = 0;
  void build(int L, const double* cs, const double* sn);
  // cos (sin = false) or sin of the run of parity q, from its first order 2 - q.
  const double* run(bool sin, int q) const { return (sin ? s : c).data() + (q ? odd : 2); }
};

// The quarter turn Y = T[R_y(-pi/2)] up to degree L (all orders), stored by parity: d^l(pi/2) obeys
// d_{m',-m} = (-1)^(l+m') d_{m',m}, so the cos block of degree l (row m', column m) vanishes unless
// l + m' + m is even and the sin block unless it is odd. Each block is kept as two dense matrices, rows
// of one parity of m' against the columns of the parity that pairs with it: half the numbers and half
// the products of the full blocks.
class PivotTables {
 public:
  void build(int L);
  int degree() const { return L_; }
  // Rows m' of parity pr (m' <= l; sin: m' >= 1) of degree l's cos (sin = false) or sin block against the
  // columns m of the paired parity (cos: (l + pr) % 2; sin: (l + pr + 1) % 2, m >= 1), row-major with
  // `columns` numbers a row; `inverse`: the same half of Y^-1 (the transpose, with the cos block's
  // weights s^-2 C^T s^2 of FrameRotation::from_frame), rows m, columns m'.
  struct Half {
    const double* a;
    int columns;
  };
  Half half(int l, bool sin, int pr, bool inverse = false) const {
    const std::size_t k = std::size_t(8 * l + 4 * inverse + 2 * sin + pr);
    return {&q_[off_[k]], ld_[k]};
  }
  // cos, sin of -m pi/2 (exact: 0, +-1), m = 0..L: the last z rotation of to_frame.
  const TurnTable& quarter() const { return quarter_; }

 private:
  int L_ = -1;
  std::vector<double> q_;
  std::vector<std::size_t> off_;
  std::vector<int> ld_;
  TurnTable quarter_;
};

class PivotRotation {
 public:
  // Direction e (any length > 0), degrees <= L, frame orders |m| <= M (M < 0: all).
  void build(const Vec3& e, int L, int M = -1);
  int degree() const { return L_; }
  // As FrameRotation::to_frame2 / from_frame2 (frame orders <= min(M, Mmax); from_frame2 ADDS, or writes
  // with add = false), with the quarter turns of Y (Y.degree() >= Lmax).
  void to_frame2(const PivotTables& Y, int Lmax, int Mmax, const double* in1, const double* in2, double* out1,
                 double* out2) const;
  void from_frame2(const PivotTables& Y, int Lmax, int Mmax, const double* in1, const double* in2, double* out1,
                   double* out2, bool add = true) const;

 private:
  int L_ = -1, M_ = -1;
  TurnTable a_, b_;  // cos, sin of m (a + pi/2) and of m b, m = 0..L
};

}  // namespace agglo::es::sh
