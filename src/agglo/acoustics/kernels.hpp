#pragma once
// Collision kernels beta_ij [m^3/s] (MODEL C.3; seed eqs. 7-11), one function per mechanism.
//   orthokinetic + gravitational settling (eq. 8):  (pi/4)(d_i+d_j)^2 |v_i - v_j|
//   acoustic wake effect (eq. 9):                   (3/16)(u_amp/r)(d_i+d_j)^2 (d_i l_i + d_j l_j)
//   mutual radiation pressure (eq. 10):             sqrt(3) rho_g u_amp^2/(144 pi mu_g) d_i^2 d_j^2/(d_i+d_j)
//                                                   * (d_i F_ij + d_j F_ji), F_ij = l_i l_j cos(phi_i-phi_j)/r
//                                                   (F: MODEL C.3 decision, Song 1990 not recoverable)
//   Brownian, continuum + slip (eq. 11):            (2 k_B T/(3 mu_g))(d_i+d_j)(C_c,i/d_i + C_c,j/d_j)
//   Brownian, Fuchs transition regime (Seinfeld & Pandis, Table 13.1) - option
//   test kernels: constant K0; additive B (v_i + v_j) with v = particle volume.
// l_i = omega tau_i / sqrt(1+(omega tau_i)^2), phi_i = atan(omega tau_i) (MODEL C.3 decision);
// r = centre distance floored at contact (d_i+d_j)/2.
// `bound_*` give an upper bound of the kernel over all partners j of a cell (majorant for the
// Nanbu guard, MODEL C.4).
#include <cmath>
#include <string>

#include "agglo/acoustics/gas.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/acoustics/sound.hpp"

namespace agglo::acoustics {

enum class KernelModel { acoustic, constant, additive, brownian_fuchs };
enum class BrownianForm { continuum_slip, fuchs };
KernelModel kernel_model_from_name(const std::string& name);
const char* kernel_model_name(KernelModel m);

struct KernelSettings {
  KernelModel model = KernelModel::acoustic;
  bool orthokinetic = true;        // beta_OI+GS
  bool acoustic_wake = true;       // beta_AWE
  bool radiation_pressure = true;  // beta_MRPE
  bool brownian = true;            // beta_BD
  BrownianForm brownian_form = BrownianForm::continuum_slip;
  double collision_efficiency = 1.0;  // multiplies beta_OI+GS
  double constant_coefficient = 0.0;  // K0 [m^3/s]
  double additive_coefficient = 0.0;  // B [1/s]
  bool exclude_same_population = false;  // test switch: only pairs of different populations collide
};

// Per-mechanism kernels. Quantities for one particle: diameter d, velocity, slip coefficient l etc.
double beta_orthokinetic(double di, double dj, double rel_speed);
double beta_acoustic_wake(double u_amp, double r, double di, double dj, double li, double lj);
double beta_radiation_pressure(const Gas& gas, double u_amp, double r, double di, double dj, double li, double lj,
                               double cos_dphi);
double beta_brownian_slip(const Gas& gas, double di, double dj, double cci, double ccj);
double beta_brownian_fuchs(const Gas& gas, double di, double dj, double rhoi, double rhoj);
inline double beta_constant(double k0) { return k0; }
inline double beta_additive(double b, double vi, double vj) { return b * (vi + vj); }

// Aggregates of one cell that bound the kernel of any pair (maxima over the cell's samples).
struct CellBounds {
  double d_max = 0.0;        // largest diameter
  double vol_max = 0.0;      // largest particle volume
  double dl_max = 0.0;       // largest d l
  double ccd_max = 0.0;      // largest C_c / d
  double speed_dev_max = 0.0;// largest |v - v_ref| (valid after finalize())
  double speed_dev2_max = 0.0;// its square
  double w_max = 0.0;        // largest weight
  double cbar_max = 0.0;     // largest thermal speed (Fuchs)
  double vref[3] = {0, 0, 0};// reference velocity of the cell
  bool need_cbar = false;    // track cbar_max (Fuchs only)
  void include(const SampleSet& p, std::size_t i, const Gas& gas);
  void finalize() { speed_dev_max = std::sqrt(speed_dev2_max); }
};

class Kernel {
 public:
  Kernel(KernelSettings s, const Gas& gas, const Sound& sound) : s_(s), gas_(gas), sound_(sound) {}
  const KernelSettings& settings() const { return s_; }
  // Sum of the enabled kernels for samples i, j at centre distance r.
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double r) const;
  // Upper bound of beta(i, j) over every j the cell bounds describe.
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const;
  // Upper bound of beta over every pair of the cell.
  double bound_cell(const CellBounds& cb) const;
  bool needs_distance() const;

 private:
  KernelSettings s_;
  Gas gas_;
  Sound sound_;
};

double thermal_speed(const Gas& gas, double mass);  // sqrt(8 k_B T / (pi m)) [m/s]

}  // namespace agglo::acoustics
