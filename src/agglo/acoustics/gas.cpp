#include "agglo/acoustics/gas.hpp"

#include <bit>
#include <cmath>
#include <cstdint>

#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

Gas Gas::air(double T, double P, bool gravity_on, std::optional<double> mu_override,
             std::optional<double> lambda_override) {
  using namespace agglo::constants;
  Gas g;
  g.temperature = T;
  g.pressure = P;
  const double M = g.molar_mass;
  g.density = P * M / (R_gas * T);
  g.sound_speed = std::sqrt(1.4 * R_gas * T / M);
  g.viscosity = mu_override ? *mu_override : 1.716e-5 * std::pow(T / 273.15, 1.5) * (273.15 + 110.4) / (T + 110.4);
  g.mean_speed = std::sqrt(8.0 * R_gas * T / (pi * M));
  g.mean_free_path = lambda_override ? *lambda_override : 2.0 * g.viscosity / (g.density * g.mean_speed);
  g.gravity = gravity_on ? g0 : 0.0;
  return g;
}

double Gas::slip_correction(double d) const {
  const double kn = 2.0 * mean_free_path / d;
  return 1.0 + kn * (1.257 + 0.400 * std::exp(-1.100 / kn));
}

double Gas::inertia_correction(double re) { return re > 0.0 ? 1.0 + 0.15 * std::pow(re, 0.687) : 1.0; }

namespace {
// x^0.687 for normal x > 0: exp2(0.687 log2 x) with least-squares polynomials for log2 on the
// mantissa [1, 2) (abs. error 2e-8) and 2^f on [0, 1) (rel. error 3e-12); no library calls.
inline double pow0687(double x) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  const int e = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
  const double m = std::bit_cast<double>((bits & 0xfffffffffffffULL) | 0x3ff0000000000000ULL) - 1.5;
  static constexpr double cl[10] = {0.0053452864305608885, -0.0087641958030246665, 0.011768610416923427,
                                    -0.020735617586075169, 0.038027993165034676, -0.071276131548655655,
                                    0.14248708237175639,   -0.32059796289542419, 0.96179670928780481,
                                    0.58496249642754272};
  double l = cl[0];
  for (int k = 1; k < 10; ++k) l = l * m + cl[k];
  const double y = 0.687 * (l + e);
  const double yi = std::floor(y), f = y - yi - 0.5;
  static constexpr double ce[9] = {1.874765852261758e-06, 2.1646961179905849e-05, 0.00021783765136621964,
                                   0.0018856365075522233, 0.013602088722456433, 0.078494664098601688,
                                   0.33973158418025667,   0.98025814345392825,  1.4142135623731216};
  double r = ce[0];
  for (int k = 1; k < 9; ++k) r = r * f + ce[k];
  const std::int64_t ie = static_cast<std::int64_t>(yi) + 1023;
  if (ie <= 0 || ie >= 2047) return std::pow(x, 0.687);
  return r * std::bit_cast<double>(static_cast<std::uint64_t>(ie) << 52);
}
}  // namespace

double Gas::inertia_correction_fast(double re) {
  return re >= 1e-300 ? 1.0 + 0.15 * pow0687(re) : 1.0;
}

double Gas::relaxation_time(double rho_p, double d) const {
  return rho_p * d * d * slip_correction(d) / (18.0 * viscosity);
}

}  // namespace agglo::acoustics
