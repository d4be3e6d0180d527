#pragma once
// Carrier gas (air) properties from temperature and pressure (docs/model.md §C.1; Zhao et al. 2023, section 2.1).
//   rho_g = P M / (R T)                          ideal gas                         [kg/m^3]
//   c     = sqrt(1.4 R T / M)                    speed of sound                    [m/s]
//   mu_g  = 1.716e-5 (T/273.15)^1.5 (273.15+110.4)/(T+110.4)   Sutherland          [Pa s]
//   cbar  = sqrt(8 R T / (pi M))                 mean molecular speed              [m/s]
//   lambda_g = 2 mu_g / (rho_g cbar)             mean free path                    [m]
// Viscosity and mean free path may be overridden (e.g. to compare with textbook tables).
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

namespace agglo::acoustics {

// Natural logarithm of a positive normal x (polynomial; relative error ~1e-15 except near x = 1 where
// the absolute error is ~1e-17).
inline double detail_log(double x) {
  std::uint64_t b = std::bit_cast<std::uint64_t>(x);
  int e = static_cast<int>((b >> 52) & 0x7ff) - 1023;
  double m = std::bit_cast<double>((b & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);  // [1, 2)
  if (m > 1.4142135623730951) {
    m *= 0.5;
    ++e;
  }
  const double t = (m - 1.0) / (m + 1.0), t2 = t * t;  // |t| <= 0.1716
  const double ser =
      1.0 + t2 * (1.0 / 3 + t2 * (1.0 / 5 + t2 * (1.0 / 7 + t2 * (1.0 / 9 + t2 * (1.0 / 11 + t2 * (1.0 / 13))))));
  return static_cast<double>(e) * 0.6931471805599453 + 2.0 * t * ser;
}
// e^y for |y| < 700 (2^n times a degree-11 Taylor polynomial of e^r, |r| <= ln2/2; relative error ~1e-15).
inline double detail_exp_small(double y) {
  const double n = (y * 1.4426950408889634 + 0x1.8p52) - 0x1.8p52;  // round to nearest integer
  const double r = (y - n * 0.6931471805599453) - n * 2.3190468138462996e-17;
  const double p =
      1.0 + r * (1.0 + r * (0.5 + r * (1.0 / 6 + r * (1.0 / 24 + r * (1.0 / 120 + r * (1.0 / 720 + r * (1.0 / 5040 +
      r * (1.0 / 40320 + r * (1.0 / 362880 + r * (1.0 / 3628800 + r * (1.0 / 39916800)))))))))));
  const std::uint64_t sc = static_cast<std::uint64_t>(static_cast<std::int64_t>(n) + 1023) << 52;
  return p * std::bit_cast<double>(sc);
}

struct Gas {
  double temperature = 298.15;   // T [K]
  double pressure = 101325.0;    // P [Pa]
  double molar_mass = 0.0289647; // M [kg/mol]
  double density = 0.0;          // rho_g [kg/m^3]
  double sound_speed = 0.0;      // c [m/s]
  double viscosity = 0.0;        // mu_g [Pa s]
  double mean_speed = 0.0;       // cbar [m/s]
  double mean_free_path = 0.0;   // lambda_g [m]
  double gravity = 0.0;          // |g| [m/s^2], acting along -z; 0 when gravity is off

  static Gas air(double T, double P, bool gravity_on, std::optional<double> mu_override = std::nullopt,
                 std::optional<double> lambda_override = std::nullopt);

  // Cunningham slip correction (Zhao et al. 2023, eq. 5): C_c = 1 + Kn [1.257 + 0.400 exp(-1.100/Kn)], Kn = 2 lambda/d.
  double slip_correction(double d) const;
  // Inertia (Schiller-Naumann) correction (Zhao et al. 2023, eq. 4): C_I = 1 + 0.15 Re^0.687.
  static double inertia_correction(double reynolds);
  // Same with Re^0.687 = exp(0.687 ln Re) from short polynomials (ln m = 2 atanh((m-1)/(m+1)) on the
  // mantissa, exp by 2^n e^r with |r| <= ln2/2): relative error of C_I - 1 ~1e-12 (tested < 1e-6
  // against pow); inline, no libm call (used in the motion loop).
  static double inertia_correction_fast(double reynolds) {
    if (!(reynolds > 0.0)) return 1.0;
    if (reynolds < 1e-30 || reynolds > 1e30) return inertia_correction(reynolds);
    return 1.0 + 0.15 * detail_exp_small(0.687 * detail_log(reynolds));
  }
  // Particle Reynolds number Re = |u - v| d rho_g / mu_g.
  double reynolds(double slip_speed, double d) const { return slip_speed * d * density / viscosity; }
  // Stokes relaxation time with slip, C_I = 1: tau = rho_p d^2 C_c / (18 mu_g) [s].
  double relaxation_time(double rho_p, double d) const;
};

}  // namespace agglo::acoustics
