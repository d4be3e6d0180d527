#pragma once
// A tabulated dry collision outcome (docs/acoustics.md §1.7): the probabilities P_stick, P_bounce and
// P_break of a collision on a grid of the normal relative speed v_n = |G.n| [m/s], the two partners'
// diameters d_1 <= d_2 [m] (the pair is queried with the smaller diameter first) and, optionally, their
// surface charge densities sigma_1, sigma_2 [C/m^2] (partner 1 = the one of diameter d_1), their relative
// permittivity kappa_p [1] (docs/outcomes.md "Charge and permittivity") and the primary radii a_1, a_2 [m] of
// aggregate partners (docs/acoustics.md §1.7; with the volume-equivalent diameters d = 2 a N^(1/3) they fix
// each partner's primary count; a compact sphere is one primary of radius d/2). The charge of a partner of
// (volume-equivalent) diameter d is Q = sigma pi d^2 (sigma = Q / (pi d^2): for a sphere its surface charge
// density; an aggregate's Q is spread evenly over its primaries), signed.
// Between the nodes the probabilities are interpolated multilinearly over every axis the table has, in
// ln v_n, ln d_1, ln d_2, sigma_1, sigma_2 (linear: signed), ln kappa_p, ln a_1 and ln a_2:
//   P(x) = sum over the 2^m corners c of the enclosing cell of  prod_k w_k(c) P_c,
//   w_k = (s(x_k) - s(a_k)) / (s(b_k) - s(a_k)) towards the upper node b_k of axis k (1 - w_k for a_k),
// s = ln or the identity as listed, which is exact for data that are linear in each s(x_k). A query
// outside an axis is clamped to its end node and counted (a query within 1e-9 relative of an end node
// lies on it; on a linear axis relative to max(|node|, the axis' span)). An axis of one node holds the
// table constant along it; an absent optional axis is not read at all (an uncharged table ignores
// charges: the DSMC refuses charged populations with it, acoustics/case_config.cpp).
// File: NetCDF (io/netcdf_reader.hpp), dimensions `speed`, `diameter_1`, `diameter_2` [, `charge_1`,
// `charge_2`] [, `permittivity`] [, `primary_radius_1`, `primary_radius_2`] in this order (the charge axes
// both or neither, the primary-radius axes alike), coordinate variables of the same names in "m s-1", "m",
// "m", "C m-2", "C m-2", "1", "m", "m" (strictly increasing; positive except the charges), and `p_stick`, `p_bounce`, `p_break` (units "1", over all the table's dimensions, each in
// [0, 1], their sum 1 within 1e-6 at every node); further variables (intervals, counts) and global
// attributes (provenance) are kept but not used. `agglo outcomes` writes such a file (docs/outcomes.md);
// a 3-axis file (no charge or permittivity) is the format of before those axes, read unchanged.
// Fragment statistics of a pair that breaks (required when P_break > 0 at some node, optional otherwise),
// over the same dimensions, units "1": `fragments`, the mean number of fragments N_f of one broken pair,
// and `largest_fraction`, the mean mass fraction f_L of its largest fragment. At the nodes with
// P_break > 0 they must satisfy N_f >= 2 and 1/N_f <= f_L < 1; elsewhere they are not read (NaN: no breaks
// seen). The fragment mass distribution they stand for (the model of the DSMC, fragments.hpp): one
// fragment of f_L M and N_f - 1 of (1 - f_L) M / (N_f - 1) each, M the pair's mass. Between nodes they
// are the conditional means given a break, interpolated with the weights of P_break:
//   N_f(x) = sum_c W_c P_break,c N_f,c / sum_c W_c P_break,c   (and f_L alike),
// W_c the corner weights above (by Jensen's inequality 1/N_f <= f_L still holds between the nodes).
// Fragment mass distribution (optional; docs/acoustics.md §1.7 "Fragment mass distribution"): bins of the
// fragment mass fraction f = m / M, `fragment_edges` over the dimension `fragment_edge` (B + 1 values,
// 0 = e_0 < e_1 < ... < e_B = 1, units "1"; bin b holds e_b <= f < e_(b+1), the last also f = 1, B <= 32),
// and over (the table's dimensions, `fragment_bin` of B), units "1":
//   fragment_number: h_b, the mean number of fragments in bin b of one broken pair (sum_b h_b = N_f),
//   fragment_mass:   mu_b, the mean mass fraction of M those fragments carry (sum_b mu_b = 1),
// so mu_b / h_b is the mean mass fraction of a fragment of bin b. Checked at the nodes with P_break > 0:
// both >= 0, h_b > 0 exactly where mu_b > 0, sum_b mu_b = 1 within 1e-6, e_b <= mu_b / h_b <= e_(b+1)
// (within 1e-9), sum_b h_b >= 2, and sum_b h_b = N_f (within 1e-6 relative) when `fragments` is there too.
// Between nodes: h_b(x) = sum_c W_c P_break,c h_b,c / sum_c W_c P_break,c, mu_b alike (their ratio stays in
// the bin: a mediant). A table with them needs no `fragments` / `largest_fraction`; a table without them
// is read as before (the (N_f, f_L) model).
#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "agglo/io/dataset.hpp"

namespace agglo::acoustics {

// Names, units, meanings and interpolation space of the file's dimensions/coordinates (written once,
// here), in the order of the file's dimensions; the first kRequiredOutcomeAxes are required.
inline constexpr std::size_t kOutcomeAxisCount = 8, kRequiredOutcomeAxes = 3;
enum OutcomeAxis : std::size_t {
  kSpeedAxis, kDiameter1Axis, kDiameter2Axis, kCharge1Axis, kCharge2Axis, kPermittivityAxis,
  kPrimaryRadius1Axis, kPrimaryRadius2Axis };
inline constexpr std::array<const char*, kOutcomeAxisCount> kOutcomeAxes = {
    "speed", "diameter_1", "diameter_2", "charge_1", "charge_2", "permittivity", "primary_radius_1", "primary_radius_2"};
inline constexpr std::array<const char*, kOutcomeAxisCount> kOutcomeAxisUnits = {"m s-1", "m",     "m", "C m-2",
                                                                                 "C m-2", "1",     "m", "m"};
inline constexpr std::array<const char*, kOutcomeAxisCount> kOutcomeAxisMeanings = {
    "normal relative speed at contact",
    "diameter of the smaller partner",
    "diameter of the larger partner",
    "surface charge density Q / (pi d^2) of the partner of diameter_1",
    "surface charge density Q / (pi d^2) of the partner of diameter_2",
    "relative permittivity kappa_p of both partners",
    "primary radius of the partner of diameter_1",
    "primary radius of the partner of diameter_2"};
inline constexpr std::array<bool, kOutcomeAxisCount> kOutcomeAxisLog = {true, true, true, false, false, true, true, true};
inline constexpr std::array<const char*, 3> kOutcomeProbabilities = {"p_stick", "p_bounce", "p_break"};
inline constexpr std::array<const char*, 2> kOutcomeFragmentStats = {"fragments", "largest_fraction"};
inline constexpr std::array<const char*, 2> kOutcomeFragmentMeanings = {
    "mean number of fragments of a pair that breaks",
    "mean mass fraction of the largest fragment of a pair that breaks"};
// The fragment mass distribution: bin dimension, edge dimension and variable, and the two variables over
// (table dimensions, bin): names, meanings; units "1".
inline constexpr const char* kFragmentBinDim = "fragment_bin";
inline constexpr const char* kFragmentEdgeDim = "fragment_edge";
inline constexpr const char* kFragmentEdges = "fragment_edges";
inline constexpr const char* kFragmentEdgesMeaning = "edges of the bins of the fragment mass fraction m / M";
inline constexpr std::array<const char*, 2> kFragmentDistribution = {"fragment_number", "fragment_mass"};
inline constexpr std::array<const char*, 2> kFragmentDistributionMeanings = {
    "mean number of fragments in the mass-fraction bin of a pair that breaks",
    "mean mass fraction of the pair carried by the fragments in the bin of a pair that breaks"};
inline constexpr std::size_t kMaxFragmentBins = 32;
// Optional global attributes (numbers, text): the fractal law N = k_f (R_g / a)^D_f of an aggregate table's
// structures (impact/outcome_fractal_law.hpp; both numbers or neither, D_f in (1, 3], k_f > 0) and how it was
// obtained, which a population takes with population.fractal_law = "table" (docs/acoustics.md §1.8).
inline constexpr const char* kFractalDimensionAttribute = "fractal_dimension";
inline constexpr const char* kFractalPrefactorAttribute = "fractal_prefactor";
inline constexpr const char* kFractalLawAttribute = "fractal_law";
// Of a charged sphere table (both or neither): the DEM's launch surface gap g in units of the radius of the
// smaller partner (the target), so the launch centre distance is s = r_1 + r_2 + g min(r_1, r_2) with
// r = d / 2, and the medium's relative permittivity kappa_0 of its electrostatics; the DSMC converts its
// far-field normal speed to the speed at s with them (docs/acoustics.md §1.7 "Coulomb work").
inline constexpr const char* kLaunchGapAttribute = "launch_gap";
inline constexpr const char* kMediumPermittivityAttribute = "medium_permittivity";

struct OutcomeProbabilities {
  double stick = 0.0, bounce = 0.0, brk = 0.0;
  bool clamped = false;  // the query lay outside the table on at least one axis
};

// Fragments of a pair that breaks: mean number N_f (>= 2) and mass fraction of the largest f_L.
// With a fragment mass distribution (bins > 0): per bin b < bins the mean number h_b and mass fraction
// mu_b of the fragments of one broken pair (number = sum_b h_b).
struct FragmentStats {
  double number = 2.0, largest = 0.5;
  std::size_t bins = 0;
  std::array<double, kMaxFragmentBins> bin_number{}, bin_mass{};
};

// One pair's query: normal speed [m/s], both diameters [m] (any order), their surface charge densities
// [C/m^2] (each with its own diameter), the pair's relative permittivity and both primary radii [m] (each
// with its own diameter; read only by tables with primary-radius axes).
struct OutcomeQuery {
  double speed = 0.0, d_i = 0.0, d_j = 0.0;
  double sigma_i = 0.0, sigma_j = 0.0, permittivity = 1.0;
  double rp_i = 0.0, rp_j = 0.0;
};

struct OutcomeTable {
  // speed [m/s], diameter_1 [m], diameter_2 [m], charge_1, charge_2 [C/m^2], permittivity [1], increasing;
  // an empty optional axis is absent (not a dimension of the file).
  std::array<std::vector<double>, kOutcomeAxisCount> axes;
  std::vector<double> p_stick, p_bounce, p_break;  // row-major over the present axes, in order
  std::vector<double> fragments, largest_fraction; // same layout; empty when the file has none
  std::vector<double> fragment_edges;               // B + 1 bin edges of m / M; empty: no distribution
  std::vector<double> fragment_number, fragment_mass;  // node-major, B bins innermost; empty: none
  std::size_t fragment_bins() const { return fragment_edges.empty() ? 0 : fragment_edges.size() - 1; }
  std::string source;                              // file it was read from ("" when built in memory)
  std::string provenance;                          // the file's `provenance` attribute, if any
  double fractal_dimension = 0.0, fractal_prefactor = 0.0;  // the structures' law; 0: none recorded
  std::string fractal_law;                         // how it was obtained
  double launch_gap = 0.0, medium_permittivity = 1.0;  // g [1] and kappa_0 [1]; launch_gap 0: none recorded
  bool has_fractal_law() const { return fractal_dimension > 0.0; }
  bool has_launch_gap() const { return launch_gap > 0.0; }

  // Probabilities of query q (the pair ordered by diameter, its charges with it).
  OutcomeProbabilities at(const OutcomeQuery& q) const;
  // Uncharged pair of permittivity 1: normal speed v [m/s] and diameters di, dj [m] (any order).
  OutcomeProbabilities at(double v, double di, double dj) const { return at(OutcomeQuery{v, di, dj}); }
  // Fragment statistics given a break at q (conditional interpolation above). Only for a query where
  // P_break > 0; tables without fragment statistics give the default FragmentStats.
  FragmentStats fragments_at(const OutcomeQuery& q) const;
  FragmentStats fragments_at(double v, double di, double dj) const { return fragments_at(OutcomeQuery{v, di, dj}); }
  bool has_axis(std::size_t k) const { return !axes[k].empty(); }
  bool charged() const { return has_axis(kCharge1Axis); }
  bool has_primary_radii() const { return has_axis(kPrimaryRadius1Axis); }
  // Row-major index of the node with axis indices ix (absent axes: index 0).
  std::size_t index(const std::array<std::size_t, kOutcomeAxisCount>& ix) const {
    std::size_t r = 0;
    for (std::size_t k = 0; k < kOutcomeAxisCount; ++k)
      if (has_axis(k)) r = r * axes[k].size() + ix[k];
    return r;
  }
  std::size_t index(std::size_t iv, std::size_t i1, std::size_t i2) const { return index({iv, i1, i2, 0, 0, 0, 0, 0}); }
  std::size_t nodes() const {
    std::size_t n = 1;
    for (const auto& a : axes) n *= a.empty() ? 1 : a.size();
    return n;
  }
  // The names of the present axes, in order (the dimensions of the table's variables).
  std::vector<std::string> dimensions() const;
};

// The table held by `d`; std::invalid_argument with a one-line reason (naming the variable and the
// offending value) when a variable is missing, has other dimensions or units, an axis is not
// increasing (or not positive, charges excepted), one charge axis is given without the other, a probability is outside [0, 1] or the three do not sum to 1, a fractal-law or launch-gap attribute is not a number in its range or given without its partner, or a node with
// P_break > 0 has no or invalid fragment statistics (N_f < 2, f_L outside [1/N_f, 1); the distribution's checks above).
OutcomeTable outcome_table_from_dataset(const io::Dataset& d);

// The dataset of `t` in the file format above (the inverse of outcome_table_from_dataset).
io::Dataset outcome_table_dataset(const OutcomeTable& t);

// Reads and checks a table file (io::NetcdfReadError when it cannot be read, std::invalid_argument as above).
OutcomeTable load_outcome_table(const std::filesystem::path& file);

}  // namespace agglo::acoustics
