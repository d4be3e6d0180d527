#pragma once
// Sphere-sphere collision outcomes on a grid (agglo outcomes, docs/outcomes.md): for every normal speed
// v_n of `speeds` and every pair of diameters d_1 <= d_2 of `diameters`, `impacts` DEM impacts of a sphere
// of d_2 onto a resting sphere of d_1 (the impact experiment with a one-sphere list target, docs/dem.md),
// each at an impact parameter b drawn with b^2 uniform in [0, (f (r_1 + r_2))^2] (f = max_offset; the
// hard-sphere encounter of the DSMC restricted to b <= f (r_1 + r_2)) and launched at
//   v = v_n / sqrt(1 - (b / (r_1 + r_2))^2),
// so that the normal relative speed at first contact is v_n (the DSMC queries the table at its pair's
// normal speed). An impact sticks when the spheres are in contact at the end (impact::stays), else it
// bounces; a break (fragments) cannot happen for two spheres (P_break = 0, kept for aggregate tables).
// Per node: counts and P = k/n with the 95 % Wilson score interval
//   (p + z^2/2n -+ z sqrt(p(1-p)/n + z^2/4n^2)) / (1 + z^2/n),  z = 1.959964.
// The table is symmetric: node (d_1, d_2) with d_1 > d_2 copies (d_2, d_1).
// Optional axes (docs/outcomes.md "Charge and permittivity"): `charges`, surface charge densities sigma
// [C/m^2] (signed) given to each partner, charge Q = sigma pi d^2 with d its (volume-equivalent) diameter
// (a sphere of surface density sigma; an aggregate's Q spread evenly over its primaries), run with the
// electrostatics of the case ([electrostatics]); and `permittivities`, the relative permittivity kappa_p
// of both partners. Nodes (speed, d_1, d_2, sigma_1, sigma_2, kappa_p); symmetric: (d_1, d_2, sigma_1,
// sigma_2) copies (d_2, d_1, sigma_2, sigma_1), so an equal-size pair runs sigma_1 <= sigma_2 only. Absent,
// the partners keep the case's charges and permittivities and the table has no such axes.
// Aggregate partners (outcome_grid.primaries instead of diameters, optionally over outcome_grid.primary_radii):
// impact/outcome_aggregates.hpp; their
// tables also carry, per node, the mean number of fragments and the mean mass fraction of the largest
// fragment over the impacts that broke (NaN where none broke), and the fragment mass distribution: per bin
// b of the mass fraction f = m / M (kFragmentFractionEdges: e_b <= f < e_(b+1), the last bin also f = 1),
// the mean number h_b of fragments of one broken pair in the bin and the mean mass fraction mu_b they carry
// (sum_b h_b = the mean number of fragments, sum_b mu_b = 1; NaN where none broke).
#include <array>
#include <cstdint>
#include <vector>

#include "agglo/core/estimate.hpp"
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/impact_case.hpp"

namespace agglo::impact {


// The bins of the fragment mass fraction m / M of agglo outcomes: 0, 2^(-6.5), 2^(-5.5), ..., 2^(-0.5), 1
// (a factor 2 apart; the edges lie between the fractions k/N of pairs of up to 2^6 equal primaries).
inline constexpr std::array<double, 9> kFragmentFractionEdges = {
    0.0,                0.011048543456039806, 0.02209708691207961, 0.04419417382415922, 0.08838834764831845,
    0.1767766952966369, 0.3535533905932738,   0.7071067811865476,  1.0};
// The bin b of a fragment of mass fraction f (0 <= f <= 1).
std::size_t fragment_fraction_bin(double f);

struct OutcomeGridSpec {
  std::vector<double> speeds, diameters;  // [m/s], [m] (aggregates: volume-equivalent, from primaries)
  std::vector<int> primaries;             // aggregate partners' primary counts (at primary_radii[0]); empty: spheres
  std::vector<double> charges;            // sigma [C/m^2] of each partner; empty: the case's charges
  std::vector<double> permittivities;     // kappa_p of both partners; empty: the case's
  // Primary radii a [m] of the aggregate partners (outcome_grid.primary_radii); empty: one radius,
  // primary_radius, and no primary-radius axes. The size axis is common: d_k = 2 a_0 N_k^(1/3) with
  // a_0 = primary_radii[0]; a partner of radius a_m at d_k has N_k (a_0 / a_m)^3 primaries (whole, >= 2).
  std::vector<double> primary_radii;
  double primary_radius = 0.0;            // a [m] of the aggregate partners without primary_radii
  int impacts = 8;
  double max_offset = 0.5;
  std::uint64_t seed = 1;
  bool aggregates() const { return !primaries.empty(); }
  std::size_t sizes() const { return aggregates() ? primaries.size() : diameters.size(); }
  // Nodes along the charge, permittivity and primary-radius axes (1 when absent).
  std::size_t charge_nodes() const { return charges.empty() ? 1 : charges.size(); }
  std::size_t permittivity_nodes() const { return permittivities.empty() ? 1 : permittivities.size(); }
  std::size_t radius_nodes() const { return primary_radii.empty() ? 1 : primary_radii.size(); }
  // Primary radius [m] of a partner at radius node m, and its primary count at size node i.
  double partner_radius(std::size_t m) const { return primary_radii.empty() ? primary_radius : primary_radii[m]; }
  int partner_primaries(std::size_t i, std::size_t m) const;
  // Row-major node index over (speed, size_1, size_2, charge_1, charge_2, permittivity, radius_1, radius_2).
  std::size_t node(std::size_t iv, std::size_t i1, std::size_t i2, std::size_t c1 = 0, std::size_t c2 = 0,
                   std::size_t ik = 0, std::size_t m1 = 0, std::size_t m2 = 0) const {
    const std::size_t nd = sizes(), nc = charge_nodes(), nm = radius_nodes();
    return ((((((iv * nd + i1) * nd + i2) * nc + c1) * nc + c2) * permittivity_nodes() + ik) * nm + m1) * nm + m2;
  }
  std::size_t nodes() const {
    return speeds.size() * sizes() * sizes() * charge_nodes() * charge_nodes() * permittivity_nodes() *
           radius_nodes() * radius_nodes();
  }
};

// Reads [outcome_grid] (ConfigError naming the key: axes not strictly increasing, more than 1e6 impacts,
// both or neither of diameters and primaries, a primary count that is not a whole number).
// The charge and permittivity axes are read only when set.
OutcomeGridSpec parse_outcome_grid(const ConfigSection& root);
// ConfigError unless `c` is a one-sphere list target hit by a sphere, without a wall, with time.dt = 0
// (each node's step is T0 / time.steps_per_period of its own pair).
void check_sphere_sphere(const ConfigSection& root, const ImpactCase& c);

// One impact of the grid: node (iv, i1, i2, c1, c2, ik, m1, m2) with i1 <= i2 (and (c1, m1) <= (c2, m2),
// lexicographically, when i1 = i2), sample k, b / (r_1 + r_2).
struct OutcomeImpact {
  std::size_t iv = 0, i1 = 0, i2 = 0;
  int sample = 0;
  double b_fraction = 0.0;
  std::size_t c1 = 0, c2 = 0, ik = 0;  // charge of partner 1, of partner 2, permittivity (0 when absent)
  std::size_t m1 = 0, m2 = 0;          // primary radius of partner 1, of partner 2 (0 when absent)
  bool operator==(const OutcomeImpact&) const = default;
};
// Every impact, node by node (speed outermost, then sizes, charges, permittivity, primary radii) then sample;
// fixed by the spec alone. The impact parameters are drawn per (speed, size pair, sample): every charge,
// permittivity and primary-radius node of a size pair sees the same ones (common random numbers).
std::vector<OutcomeImpact> outcome_impacts(const OutcomeGridSpec& s);
std::size_t outcome_impacts_count(const OutcomeGridSpec& s);  // outcome_impacts(s).size()
// The case of one impact (radii, offset, charges and permittivity) and its launch speed [m/s].
ImpactCase outcome_case(const ImpactCase& base, const OutcomeGridSpec& s, const OutcomeImpact& j);
double outcome_launch_speed(const OutcomeGridSpec& s, const OutcomeImpact& j);

// What the grid costs (core/estimate.hpp, docs/limits.md): per node the particle-steps bound of one impact
// (impact/estimate.hpp: run_steps_bound x 2 particles) at the launch speed of the largest impact parameter,
// times the impacts; memory of `threads` concurrent runs; output: a CSV row and results.nc values per node
// and a journal line per impact.
Estimate outcomes_estimate(const ImpactCase& base, const OutcomeGridSpec& s, int threads);

enum class PairOutcome { stick = 0, bounce = 1, brk = 2 };
// Sphere pairs: stick when in contact at the end (impact::stays) or, charged, touched and bound at the
// end (ImpactOutcome::pair_energy < 0: the pair returns and, losing energy in every contact, cannot escape;
// gas drag only binds it more); else bounce (also a pair turned back before touching).
PairOutcome classify_pair(const ImpactOutcome& o);

struct WilsonInterval {
  double lo = 0.0, hi = 1.0;
};
WilsonInterval wilson_interval(std::int64_t k, std::int64_t n);

// Counts per node over the full grid (speed, diameter_1, diameter_2[, charge_1, charge_2][, permittivity]
// [, primary_radius_1, primary_radius_2]), row-major (OutcomeGridSpec::node), mirrored.
struct OutcomeGridResult {
  OutcomeGridSpec spec;
  std::vector<std::int64_t> sticks, bounces, breaks, impacts;
  // Aggregates only (else empty): over the node's impacts that broke, the mean number of fragments and
  // the mean mass fraction of the largest [1]; NaN where none broke. The mean fraction is raised to
  // 1/(mean number) when below it by a rounding error only (equal fragments; the DSMC requires f_L >= 1/N_f).
  std::vector<double> fragments, largest_fraction;
  // Aggregates whose every break has its fragments' mass fractions (else empty): h_b and mu_b per node,
  // node-major with the kFragmentFractionEdges bins innermost; NaN where none broke.
  std::vector<double> fragment_number, fragment_mass;
  std::size_t index(std::size_t iv, std::size_t i1, std::size_t i2, std::size_t c1 = 0, std::size_t c2 = 0,
                    std::size_t ik = 0, std::size_t m1 = 0, std::size_t m2 = 0) const {
    return spec.node(iv, i1, i2, c1, c2, ik, m1, m2);
  }
};
// `outcomes[k]` is the outcome of impact k of outcome_impacts(spec); for aggregates `fragments[k]` and
// `largest[k]` its number of fragments and largest mass fraction (read where outcomes[k] is a break), and
// `fractions[k]` the mass fractions of its fragments (the distribution is tabulated only when every break
// has them: a journal of before them gives none).
OutcomeGridResult tabulate_outcomes(const OutcomeGridSpec& spec, const std::vector<PairOutcome>& outcomes,
                                    const std::vector<double>& fragments = {},
                                    const std::vector<double>& largest = {},
                                    const std::vector<std::vector<double>>& fractions = {});

}  // namespace agglo::impact
