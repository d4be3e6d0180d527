#pragma once
// Diagnostics of a sampled state (docs/model.md §C.6):
//  - number concentrations by phase (sum of weights / box volume) [1/m^3];
//  - fine efficiency eta(t) = (N_f,0 - N_f(t)) / N_f,0 where N_f counts particles without liquid
//    (decision: "fine" = solid phase);
//  - fraction of droplets still pure = N_liquid(t) / N_liquid(0);
//  - dN/dlog10 d by phase on log-spaced bins [1/m^3];
//  - total solid and liquid volume per box volume (conservation checks) [m^3/m^3];
//  - PM1, PM2.5, PM10 mass concentrations (pm_mass below) [kg/m^3].
#include <array>
#include <vector>

#include "agglo/acoustics/gas.hpp"
#include "agglo/acoustics/samples.hpp"

namespace agglo::acoustics {

struct Counts {
  double n_total = 0.0;
  std::array<double, 3> n_phase{};      // by Phase: solid, liquid, mixed [1/m^3]
  double solid_volume = 0.0;            // sum w V_s / V
  double liquid_volume = 0.0;           // sum w V_l / V
  double mass = 0.0;                    // sum w m / V
  std::size_t live_samples = 0;
};
Counts count(const SampleSet& p, double box_volume);

struct PsdBins {
  std::vector<double> edges;  // diameters [m], size K+1, log spaced
  static PsdBins log_spaced(double dmin, double dmax, int k);
  int find(double d) const;   // -1 outside
};

// PM mass concentrations: the mass (solid + liquid, every phase) per box volume of the particles whose
// diameter is below the cut x = 1, 2.5, 10 um (a sharp cut: d < x counts, d >= x does not) [kg/m^3],
// for two diameters:
//  - volume-equivalent d_v (the sample's diameter d);
//  - aerodynamic d_a: the diameter of the sphere of density rho_0 = 1000 kg/m^3 that settles at the same
//    speed (Hinds, Aerosol Technology, 2nd ed. 1999, sec. 3.11; spheres: dynamic shape factor 1),
//      d_a = d_v sqrt(rho_p C_c(d_v) / (rho_0 C_c(d_a))),
//    C_c the Cunningham correction of the case's gas (Gas::slip_correction). d^2 C_c(d) increases with d,
//    so d_a < x iff rho_p d_v^2 C_c(d_v) < rho_0 x^2 C_c(x): pm_mass classifies by that test (no
//    iteration); aerodynamic_diameter gives d_a itself.
//    An aggregate (structure.hpp) settles with its relaxation time tau = m C_c(d_m) / (3 pi mu_g d_m), so
//    its test is 6 m C_c(d_m) / (pi d_m) < rho_0 x^2 C_c(x) (18 mu_g tau; rho_p d_v^2 C_c(d_v) for a sphere).
//    psd.csv and the cut by volume use d_v in every run.
inline constexpr std::array<double, 3> kPmCuts = {1e-6, 2.5e-6, 10e-6};     // [m]
inline constexpr std::array<const char*, 3> kPmNames = {"pm1", "pm2_5", "pm10"};  // output names
inline constexpr std::array<const char*, 3> kPmLabels = {"PM1", "PM2.5", "PM10"};  // run.log, long names
inline constexpr double kPmUnitDensity = 1000.0;                           // rho_0 [kg/m^3]
inline constexpr double kMicrogramsPerKg = 1e9;                            // PM is reported in ug/m^3

struct PmMass {
  std::array<double, 3> volume{};       // by cut, volume-equivalent diameter [kg/m^3]
  std::array<double, 3> aerodynamic{};  // by cut, aerodynamic diameter [kg/m^3]
};
PmMass pm_mass(const SampleSet& p, double box_volume, const Gas& g);
// Fraction removed since t = 0: 1 - now / initial (0 when initial is 0).
inline double pm_reduction(double initial, double now) { return initial > 0.0 ? 1.0 - now / initial : 0.0; }

// d_a of a sphere of diameter dv [m] and density rho_p [kg/m^3] in gas g [m]: the fixed point of
// d <- d_v sqrt(rho_p C_c(d_v) / (rho_0 C_c(d))) from d = d_v sqrt(rho_p / rho_0), iterated until the
// relative change is below 1e-13 (the map contracts: |d ln(...)/d ln d| < 1/2; at most 60 iterations).
double aerodynamic_diameter(const Gas& g, double dv, double rho_p);

// dN/dlog10 d for each phase (index by Phase) and all particles (index 3).
std::array<std::vector<double>, 4> psd(const SampleSet& p, double box_volume, const PsdBins& bins);

}  // namespace agglo::acoustics
