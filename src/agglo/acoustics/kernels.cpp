#include "agglo/acoustics/kernels.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"
#include "agglo/core/error.hpp"

namespace agglo::acoustics {

using constants::k_B;
using constants::pi;

KernelModel kernel_model_from_name(const std::string& n) {
  if (n == "acoustic") return KernelModel::acoustic;
  if (n == "constant") return KernelModel::constant;
  if (n == "additive") return KernelModel::additive;
  if (n == "brownian_fuchs") return KernelModel::brownian_fuchs;
  throw ConfigError("unknown kernel model '" + n + "' (acoustic, constant, additive, brownian_fuchs)");
}

const char* kernel_model_name(KernelModel m) {
  switch (m) {
    case KernelModel::acoustic: return "acoustic";
    case KernelModel::constant: return "constant";
    case KernelModel::additive: return "additive";
    case KernelModel::brownian_fuchs: return "brownian_fuchs";
  }
  return "?";
}

double beta_orthokinetic(double di, double dj, double rel_speed) {
  const double s = di + dj;
  return 0.25 * pi * s * s * rel_speed;
}

double beta_acoustic_wake(double u_amp, double r, double di, double dj, double li, double lj) {
  const double s = di + dj;
  r = std::max(r, 0.5 * s);
  return 0.1875 * (u_amp / r) * s * s * (di * li + dj * lj);
}

double beta_radiation_pressure(const Gas& gas, double u_amp, double r, double di, double dj, double li, double lj,
                               double cos_dphi) {
  const double s = di + dj;
  r = std::max(r, 0.5 * s);
  const double f = li * lj * cos_dphi / r;  // F_ij = F_ji (MODEL C.3 decision)
  const double pref = std::sqrt(3.0) * gas.density * u_amp * u_amp / (144.0 * pi * gas.viscosity);
  return pref * di * di * dj * dj / s * (di * f + dj * f);
}

double beta_brownian_slip(const Gas& gas, double di, double dj, double cci, double ccj) {
  return 2.0 * k_B * gas.temperature / (3.0 * gas.viscosity) * (di + dj) * (cci / di + ccj / dj);
}

double thermal_speed(const Gas& gas, double mass) { return std::sqrt(8.0 * k_B * gas.temperature / (pi * mass)); }

double beta_brownian_fuchs(const Gas& gas, double di, double dj, double rhoi, double rhoj) {
  auto props = [&](double d, double rho, double& D, double& c, double& g) {
    D = k_B * gas.temperature * gas.slip_correction(d) / (3.0 * pi * gas.viscosity * d);
    c = thermal_speed(gas, rho * pi * d * d * d / 6.0);
    const double l = 8.0 * D / (pi * c);
    g = (std::pow(d + l, 3) - std::pow(d * d + l * l, 1.5)) / (3.0 * d * l) - d;
  };
  double Di, ci, gi, Dj, cj, gj;
  props(di, rhoi, Di, ci, gi);
  props(dj, rhoj, Dj, cj, gj);
  const double ds = di + dj, Ds = Di + Dj;
  const double gs = std::sqrt(gi * gi + gj * gj), cs = std::sqrt(ci * ci + cj * cj);
  return 2.0 * pi * Ds * ds / (ds / (ds + 2.0 * gs) + 8.0 * Ds / (ds * cs));
}

bool Kernel::needs_distance() const {
  return s_.model == KernelModel::acoustic && (s_.acoustic_wake || s_.radiation_pressure);
}

double Kernel::beta(const SampleSet& p, std::size_t i, std::size_t j, double r) const {
  switch (s_.model) {
    case KernelModel::constant: return beta_constant(s_.constant_coefficient);
    case KernelModel::additive: return beta_additive(s_.additive_coefficient, p.volume(i), p.volume(j));
    case KernelModel::brownian_fuchs: return beta_brownian_fuchs(gas_, p.d[i], p.d[j], p.rho[i], p.rho[j]);
    case KernelModel::acoustic: break;
  }
  double b = 0.0;
  const double di = p.d[i], dj = p.d[j];
  if (s_.orthokinetic) {
    const double gx = p.vx[i] - p.vx[j], gy = p.vy[i] - p.vy[j], gz = p.vz[i] - p.vz[j];
    b += s_.collision_efficiency * beta_orthokinetic(di, dj, std::sqrt(gx * gx + gy * gy + gz * gz));
  }
  if (s_.acoustic_wake) b += beta_acoustic_wake(sound_.u_amp, r, di, dj, p.slip_l[i], p.slip_l[j]);
  if (s_.radiation_pressure) {
    const double cdphi = p.cphi[i] * p.cphi[j] + p.sphi[i] * p.sphi[j];
    b += beta_radiation_pressure(gas_, sound_.u_amp, r, di, dj, p.slip_l[i], p.slip_l[j], cdphi);
  }
  if (s_.brownian) {
    b += s_.brownian_form == BrownianForm::fuchs ? beta_brownian_fuchs(gas_, di, dj, p.rho[i], p.rho[j])
                                                 : beta_brownian_slip(gas_, di, dj, p.cc[i], p.cc[j]);
  }
  return b;
}

void CellBounds::include(const SampleSet& p, std::size_t i, const Gas& gas) {
  d_max = std::max(d_max, p.d[i]);
  vol_max = std::max(vol_max, p.volume(i));
  dl_max = std::max(dl_max, p.dl[i]);
  ccd_max = std::max(ccd_max, p.ccd[i]);
  w_max = std::max(w_max, p.w[i]);
  const double ex = p.vx[i] - vref[0], ey = p.vy[i] - vref[1], ez = p.vz[i] - vref[2];
  const double s2 = ex * ex + ey * ey + ez * ez;
  if (s2 > speed_dev2_max) {
    speed_dev2_max = s2;
    speed_dev_max = std::sqrt(s2);
  }
  if (need_cbar) cbar_max = std::max(cbar_max, thermal_speed(gas, p.mass[i]));
}

double Kernel::bound_cell(const CellBounds& cb) const {
  const double sd = 2.0 * cb.d_max;
  switch (s_.model) {
    case KernelModel::constant: return s_.constant_coefficient;
    case KernelModel::additive: return s_.additive_coefficient * 2.0 * cb.vol_max;
    case KernelModel::brownian_fuchs: return 0.25 * pi * sd * sd * std::sqrt(2.0) * cb.cbar_max;
    case KernelModel::acoustic: break;
  }
  double b = 0.0;
  if (s_.orthokinetic) b += s_.collision_efficiency * beta_orthokinetic(cb.d_max, cb.d_max, 2.0 * cb.speed_dev_max);
  if (s_.acoustic_wake) b += 0.375 * sound_.u_amp * sd * 2.0 * cb.dl_max;
  if (s_.radiation_pressure) {
    const double pref = std::sqrt(3.0) * gas_.density * sound_.u_amp * sound_.u_amp / (144.0 * pi * gas_.viscosity);
    b += 2.0 * pref * cb.d_max * cb.d_max * cb.d_max;
  }
  if (s_.brownian) {
    double bd = 2.0 * k_B * gas_.temperature / (3.0 * gas_.viscosity) * sd * 2.0 * cb.ccd_max;
    if (s_.brownian_form == BrownianForm::fuchs) bd = std::max(bd, 0.25 * pi * sd * sd * std::sqrt(2.0) * cb.cbar_max);
    b += bd;
  }
  return b;
}

double Kernel::bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const {
  const double di = p.d[i];
  const double sd = di + cb.d_max;
  switch (s_.model) {
    case KernelModel::constant: return s_.constant_coefficient;
    case KernelModel::additive: return s_.additive_coefficient * (p.volume(i) + cb.vol_max);
    case KernelModel::brownian_fuchs: {
      // Fuchs <= free-molecular limit (pi/4)(d_i+d_j)^2 sqrt(c_i^2 + c_j^2).
      const double ci = thermal_speed(gas_, p.mass[i]);
      return 0.25 * pi * sd * sd * std::sqrt(ci * ci + cb.cbar_max * cb.cbar_max);
    }
    case KernelModel::acoustic: break;
  }
  double b = 0.0;
  if (s_.orthokinetic) {
    const double ex = p.vx[i] - cb.vref[0], ey = p.vy[i] - cb.vref[1], ez = p.vz[i] - cb.vref[2];
    b += s_.collision_efficiency * beta_orthokinetic(di, cb.d_max, std::sqrt(ex * ex + ey * ey + ez * ez) +
                                                                        cb.speed_dev_max);
  }
  // With r >= (d_i+d_j)/2: AWE <= (3/8) u_amp (d_i+d_j)(d_i l_i + max d l).
  if (s_.acoustic_wake) b += 0.375 * sound_.u_amp * sd * (p.dl[i] + cb.dl_max);
  // MRPE <= 2 pref d_i^2 d_j^2 / (d_i+d_j) <= 2 pref d_i d_max min(d_i, d_max) (l <= 1, cos <= 1).
  if (s_.radiation_pressure) {
    const double pref = std::sqrt(3.0) * gas_.density * sound_.u_amp * sound_.u_amp / (144.0 * pi * gas_.viscosity);
    b += 2.0 * pref * di * cb.d_max * std::min(di, cb.d_max);
  }
  if (s_.brownian) {
    // Fuchs <= continuum+slip form is not guaranteed; use the larger of it and the free-molecular bound.
    double bd = 2.0 * k_B * gas_.temperature / (3.0 * gas_.viscosity) * sd * (p.ccd[i] + cb.ccd_max);
    if (s_.brownian_form == BrownianForm::fuchs) {
      const double ci = thermal_speed(gas_, p.mass[i]);
      bd = std::max(bd, 0.25 * pi * sd * sd * std::sqrt(ci * ci + cb.cbar_max * cb.cbar_max));
    }
    b += bd;
  }
  return b;
}

}  // namespace agglo::acoustics
