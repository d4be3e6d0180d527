#pragma once
// Initial sampled populations (docs/model.md §C.6).
//  - lognormal (d_g, sigma_g): K log-spaced bins on [d_g sigma_g^-z, d_g sigma_g^z] (z = lognormal_range), equal numbers
//    of samples per bin (lognormal_weights = "by_bin"; "equal": equal weights at stratified quantiles
//    of the whole range), bin number from the lognormal integral (renormalised to the truncated
//    range so that sum w = N_tot V); diameters at stratified quantiles of the lognormal within the bin.
//  - monodisperse (d), exponential in volume (n(v) = N0/v0 e^(-v/v0); stratified quantiles, equal
//    weights), table (listed diameters with number fractions; equal samples per entry).
// Weights are rounded to integers >= 1 (Zhao et al. 2023, eqs. 18-21 act on integer weights): "nearest" rounds
// each sample's real number (default; the total can be off by up to 0.5 per sample, e.g. -7.5 % for
// 3200 samples of 5.41 droplets each), "conserving" rounds the running sum so that the weights add
// up to N_tot V within 0.5 (samples then differ by one in weight).
// The samples are then split into clones and placed over the cells as set by [sampling]
// (initial_placement.hpp: stratified or uniform in the box; counter-based RNG keyed by population and sample).
// A fractal population (structure.hpp) draws the same volume-equivalent diameters; each solid sample is then
// an aggregate of n_p = (d / (2 r_p))^3 primaries of radius r_p (below one primary: a compact sphere), so
// its collision diameter exceeds d. The caller sets SampleSet::structure_laws before sampling.
#include <cstdint>
#include <string>
#include <vector>

#include "agglo/acoustics/drag.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/acoustics/initial_placement.hpp"
#include "agglo/core/settings_acoustic.hpp"

namespace agglo::acoustics {

// Density of a population that does not set one [kg/m^3] (population.density).
inline constexpr double kDefaultSolidDensity = 2500.0;
inline constexpr double kDefaultLiquidDensity = 1000.0;

enum class Distribution { lognormal, monodisperse, exponential, table };

struct PopulationSpec {
  std::string name;
  Phase phase = Phase::solid;                  // solid or liquid
  Distribution distribution = Distribution::monodisperse;
  double geometric_mean_diameter = 0.0;        // d_g [m]
  double geometric_std = 2.0;                  // sigma_g
  int bins = static_cast<int>(settings::acoustic_settings().population.bins.def());  // lognormal bins K
  double lognormal_range = settings::acoustic_settings().population.lognormal_range.def();  // +- z sampled
  bool lognormal_equal_weights = false;  // equal weights at stratified quantiles instead of per-bin weights
  double diameter = 0.0;                       // monodisperse [m]
  double mean_volume = 0.0;                    // exponential v0 [m^3]
  std::vector<double> table_diameters;         // [m]
  std::vector<double> table_fractions;         // number fractions
  double number_concentration = 0.0;           // [1/m^3]
  double density = kDefaultLiquidDensity;     // [kg/m^3]
  long samples = 0;
  bool conserving_rounding = false;            // weight_rounding = "conserving"
  StructureLaw structure;                      // compact (default) or fractal aggregates (structure.hpp)
  bool charged = false;                        // population.charge_density set
  double charge_density = 0.0;                 // sigma [C/m^2]: q = sigma pi d_v^2 per particle at t = 0
  double permittivity = 1.0;                   // kappa_p (outcome tables with a permittivity axis)
};

struct SampledPopulation {
  std::size_t first = 0, count = 0;  // samples [first, first + count) of the SampleSet, clones included
  std::size_t requested = 0;         // population.samples (before cloning)
  std::int64_t clone_factor = 1;     // k of initial_placement.hpp
  double real_number = 0.0;    // N_tot V requested
  double weight_sum = 0.0;     // after integer rounding
};

// The law of every population when one of them is fractal, else none (compact run).
std::vector<StructureLaw> structure_laws_of(const std::vector<PopulationSpec>& pops);

SampledPopulation sample_population(const PopulationSpec& spec, int index, const Domain& dom, std::uint64_t seed,
                                    const Gas& gas, const Sound& sound, SampleSet& p,
                                    const SamplingSettings& sampling = {});

// Standard normal distribution: Phi(z) = erfc(-z / sqrt 2) / 2, and its quantile: the bisection of
// Phi(z) = q on [-40, 40] down to an interval of 1e-14 (normal_quantile_bisection, the reference).
// normal_quantile returns bit for bit the same number, evaluating Phi only where the bisection's
// midpoints fall inside a checked bracket of the root (Acklam's approximation, one Halley step).
double normal_cdf(double z);
double normal_quantile(double q);
double normal_quantile_bisection(double q);

}  // namespace agglo::acoustics
