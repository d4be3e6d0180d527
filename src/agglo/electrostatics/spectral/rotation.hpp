#pragma once
// Rotation of spherical-harmonic coefficient vectors (basis of harmonics.hpp) into the frame in
// which a given direction e becomes the z axis, and back. Used for the O(L^3) rotation-based
// multipole-to-local translation (rotate, axial translation, rotate back).
//
// e = (sin b cos a, sin b sin a, cos b). The frame map is Q = R_y(-b) R_z(-a) (Q e = z):
// to_frame returns c' with f(x) = sum c_lm Y_lm(x) = sum c'_lm Y_lm(Q x). The z rotation is a
// 2x2 mixing of (cos, sin) pairs; the y rotation splits into a "cos" block ((l+1)^2 entries)
// and a "sin" block (l^2 entries) per degree, built from Wigner's small d^l(b) computed by the
// stable three-term recurrence in l (cost O(L^3) per direction, done once per pair and solve).
#include <algorithm>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::es::sh {

// log k! and sqrt(j^2 - m^2) with inverses, the tables of the Wigner-d recurrence (grow only).
struct RotationTables {
  std::vector<double> lf, sq, isq, ij;
  int sqL = -1;
};
void grow_tables(RotationTables& t, int L);

class FrameRotation {
 public:
  // Build for direction e (any length > 0), degrees <= L and frame orders |m| <= M (M < 0: all).
  // With M < L only frame orders <= M are produced by to_frame / consumed by from_frame.
  void build(const Vec3& e, int L, int M = -1);
  int degree() const { return L_; }
  // out = coefficients in the rotated frame; degrees <= Lmax (<= degree()) are used.
  void to_frame(int Lmax, const double* in, double* out) const;
  // Inverse of to_frame.
  void from_frame(int Lmax, const double* in, double* out) const;
  // Fused versions for two vectors (one pass over the rotation data). to_frame2 computes only
  // the frame orders |m| <= Mmax (others untouched); from_frame2 reads only |m| <= Mmax and
  // ADDS the result to out1, out2 (degrees <= Lmax, every order), or writes it there with add = false (the
  // same numbers as adding to zeros, but for the sign of a zero).
  void to_frame2(int Lmax, int Mmax, const double* in1, const double* in2, double* out1, double* out2) const;
  void from_frame2(int Lmax, int Mmax, const double* in1, const double* in2, double* out1, double* out2,
                   bool add = true) const;
  // Degree l's blocks of to_frame (after the z rotation): cos block rows m' = 0..min(l, M), columns
  // m = 0..l (row-major), sin block rows m' = 1..min(l, M), columns m = 1..l (pivot_rotation.hpp).
  const double* cos_block(int l) const { return &blk_[off_[l]]; }
  const double* sin_block(int l) const { return &blk_[off_[l]] + (std::min(l, M_) + 1) * (l + 1); }

 private:
  void wigner_d(double b, const std::vector<std::size_t>& doff, const RotationTables& t,
                std::vector<double>& d) const;
  void real_blocks(const std::vector<std::size_t>& doff, const std::vector<double>& d);
  int L_ = -1, M_ = -1;
  std::vector<double> cosa_, sina_;   // cos(m a), sin(m a), m = 0..L
  std::vector<double> blk_;           // per l: cos block (l+1)^2 then sin block l^2, row-major
  std::vector<int> off_;              // offset of degree l's blocks in blk_
};

}  // namespace agglo::es::sh
