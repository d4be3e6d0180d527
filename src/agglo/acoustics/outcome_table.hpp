#pragma once
// A tabulated dry collision outcome (docs/acoustics.md §1.7): the probabilities P_stick, P_bounce and
// P_break of a sphere-sphere collision on a grid of the normal relative speed v_n = |G.n| [m/s] and the
// two partners' diameters d_1 <= d_2 [m] (the pair is queried with the smaller diameter first).
// Between the nodes the probabilities are interpolated multilinearly in (ln v_n, ln d_1, ln d_2):
//   P(x) = sum over the 8 corners c of the enclosing cell of  prod_k w_k(c) P_c,
//   w_k = (ln x_k - ln a_k) / (ln b_k - ln a_k) towards the upper node b_k of axis k (1 - w_k for a_k),
// which is exact for data that are linear in each of ln v_n, ln d_1 and ln d_2. A query outside an axis
// is clamped to its end node and counted (a query within 1e-9 relative of an end node lies on it). An axis of one node holds the table constant along it.
// File: NetCDF (io/netcdf_reader.hpp), dimensions `speed`, `diameter_1`, `diameter_2`, coordinate
// variables of the same names in "m s-1", "m", "m" (strictly increasing, positive), and `p_stick`,
// `p_bounce`, `p_break` (units "1", over (speed, diameter_1, diameter_2), each in [0, 1], their sum 1
// within 1e-6 at every node); further variables (intervals, counts) and global attributes (provenance)
// are kept but not used. `agglo outcomes` writes such a file (docs/outcomes.md).
// Fragment statistics of a pair that breaks (required when P_break > 0 at some node, optional otherwise),
// over the same dimensions, units "1": `fragments`, the mean number of fragments N_f of one broken pair,
// and `largest_fraction`, the mean mass fraction f_L of its largest fragment. At the nodes with
// P_break > 0 they must satisfy N_f >= 2 and 1/N_f <= f_L < 1; elsewhere they are not read (NaN: no breaks
// seen). The fragment mass distribution they stand for (the model of the DSMC, fragments.hpp): one
// fragment of f_L M and N_f - 1 of (1 - f_L) M / (N_f - 1) each, M the pair's mass. Between nodes they
// are the conditional means given a break, interpolated with the weights of P_break:
//   N_f(x) = sum_c W_c P_break,c N_f,c / sum_c W_c P_break,c   (and f_L alike),
// W_c the corner weights above (by Jensen's inequality 1/N_f <= f_L still holds between the nodes).
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "agglo/io/dataset.hpp"

namespace agglo::acoustics {

// Names of the file's dimensions/coordinates and probability variables (written once, here).
inline constexpr std::array<const char*, 3> kOutcomeAxes = {"speed", "diameter_1", "diameter_2"};
inline constexpr std::array<const char*, 3> kOutcomeAxisUnits = {"m s-1", "m", "m"};
inline constexpr std::array<const char*, 3> kOutcomeProbabilities = {"p_stick", "p_bounce", "p_break"};
inline constexpr std::array<const char*, 2> kOutcomeFragmentStats = {"fragments", "largest_fraction"};
inline constexpr std::array<const char*, 2> kOutcomeFragmentMeanings = {
    "mean number of fragments of a pair that breaks",
    "mean mass fraction of the largest fragment of a pair that breaks"};

struct OutcomeProbabilities {
  double stick = 0.0, bounce = 0.0, brk = 0.0;
  bool clamped = false;  // the query lay outside the table on at least one axis
};

// Fragments of a pair that breaks: mean number N_f (>= 2) and mass fraction of the largest f_L.
struct FragmentStats {
  double number = 2.0, largest = 0.5;
};

struct OutcomeTable {
  std::array<std::vector<double>, 3> axes;  // speed [m/s], diameter_1 [m], diameter_2 [m], increasing
  std::vector<double> p_stick, p_bounce, p_break;  // row-major over (speed, diameter_1, diameter_2)
  std::vector<double> fragments, largest_fraction; // same layout; empty when the file has none
  std::string source;                              // file it was read from ("" when built in memory)
  std::string provenance;                          // the file's `provenance` attribute, if any

  // Probabilities at normal speed v [m/s] and diameters di, dj [m] (any order: queried as (min, max)).
  OutcomeProbabilities at(double v, double di, double dj) const;
  // Fragment statistics given a break at (v, di, dj) (conditional interpolation above). Only for a
  // query where P_break > 0; tables without fragment statistics give the default FragmentStats.
  FragmentStats fragments_at(double v, double di, double dj) const;
  std::size_t index(std::size_t iv, std::size_t i1, std::size_t i2) const {
    return (iv * axes[1].size() + i1) * axes[2].size() + i2;
  }
};

// The table held by `d`; std::invalid_argument with a one-line reason (naming the variable and the
// offending value) when a variable is missing, has other dimensions or units, an axis is not
// increasing and positive, a probability is outside [0, 1] or the three do not sum to 1, or a node with
// P_break > 0 has no or invalid fragment statistics (N_f < 2, f_L outside [1/N_f, 1)).
OutcomeTable outcome_table_from_dataset(const io::Dataset& d);

// The dataset of `t` in the file format above (the inverse of outcome_table_from_dataset).
io::Dataset outcome_table_dataset(const OutcomeTable& t);

// Reads and checks a table file (io::NetcdfReadError when it cannot be read, std::invalid_argument as above).
OutcomeTable load_outcome_table(const std::filesystem::path& file);

}  // namespace agglo::acoustics
