#include "agglo/acoustics/outcome_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "agglo/io/netcdf_reader.hpp"

namespace agglo::acoustics {

namespace {

// Lower node and weight of the upper node for x on a log axis; clamps (and flags) outside it.
struct AxisPos {
  std::size_t lo = 0;
  double w = 0.0;
};

// A query within this relative distance of an end node lies on it (diameters computed from volumes
// reach a node only up to rounding): clamped to it, but not counted as outside.
constexpr double kOnNode = 1e-9;

bool off_node(double x, double node, double scale) { return !(std::abs(x - node) <= kOnNode * scale); }

// Position of x on a log axis (speed, diameters, permittivity); `clamped` is set when x lies off it.
AxisPos locate_log(const std::vector<double>& a, double x, bool& clamped) {
  if (a.size() == 1) {
    if (off_node(x, a[0], a[0])) clamped = true;
    return {};
  }
  if (!(x > a.front())) {  // also x <= 0 and NaN
    if (off_node(x, a.front(), a.front())) clamped = true;
    return {};
  }
  if (x >= a.back()) {
    if (off_node(x, a.back(), a.back())) clamped = true;
    return {a.size() - 2, 1.0};
  }
  const std::size_t hi = static_cast<std::size_t>(std::upper_bound(a.begin(), a.end(), x) - a.begin());
  const std::size_t lo = hi - 1;
  return {lo, std::log(x / a[lo]) / std::log(a[hi] / a[lo])};
}

// Position of x on a linear axis (the signed charges): on a node within 1e-9 of max(|node|, the span).
AxisPos locate_linear(const std::vector<double>& a, double x, bool& clamped) {
  const double span = a.back() - a.front();
  const auto scale = [span](double node) { return std::max(std::abs(node), span); };
  if (a.size() == 1) {
    if (off_node(x, a[0], scale(a[0]))) clamped = true;
    return {};
  }
  if (!(x > a.front())) {  // also NaN
    if (off_node(x, a.front(), scale(a.front()))) clamped = true;
    return {};
  }
  if (x >= a.back()) {
    if (off_node(x, a.back(), scale(a.back()))) clamped = true;
    return {a.size() - 2, 1.0};
  }
  const std::size_t hi = static_cast<std::size_t>(std::upper_bound(a.begin(), a.end(), x) - a.begin());
  const std::size_t lo = hi - 1;
  return {lo, (x - a[lo]) / (a[hi] - a[lo])};
}

const io::Variable& variable(const io::Dataset& d, const char* name, const std::vector<std::string>& dims,
                             const char* units) {
  const io::Variable* v = d.find(name);
  if (!v) throw std::invalid_argument(fmt::format("no variable '{}'", name));
  if (v->dims != dims)
    throw std::invalid_argument(fmt::format("variable '{}' is over ({}), expected ({})", name,
                                            fmt::join(v->dims, ", "), fmt::join(dims, ", ")));
  if (v->units != units)
    throw std::invalid_argument(fmt::format("variable '{}' has units \"{}\", expected \"{}\"", name, v->units, units));
  return *v;
}

std::vector<double> values_of(const io::Variable& v) {
  if (!v.integer) return v.reals;
  return {v.ints.begin(), v.ints.end()};
}

void check_axis(std::size_t axis, const std::vector<double>& a) {
  const char* name = kOutcomeAxes[axis];
  if (a.empty()) throw std::invalid_argument(fmt::format("axis '{}' is empty", name));
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!std::isfinite(a[k]) || (kOutcomeAxisLog[axis] && !(a[k] > 0.0)))
      throw std::invalid_argument(fmt::format("axis '{}' value {} = {} is not a {}number", name, k, a[k],
                                              kOutcomeAxisLog[axis] ? "positive " : "finite "));
    if (k > 0 && !(a[k] > a[k - 1]))
      throw std::invalid_argument(fmt::format("axis '{}' is not strictly increasing at value {} ({} after {})", name,
                                              k, a[k], a[k - 1]));
  }
}

void check_probabilities(const OutcomeTable& t) {
  const std::array<const std::vector<double>*, 3> ps = {&t.p_stick, &t.p_bounce, &t.p_break};
  for (std::size_t i = 0; i < t.p_stick.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      const double p = (*ps[k])[i];
      if (!(p >= 0.0 && p <= 1.0))
        throw std::invalid_argument(fmt::format("{} at node {} = {} is outside [0, 1]", kOutcomeProbabilities[k], i, p));
    }
    const double sum = t.p_stick[i] + t.p_bounce[i] + t.p_break[i];
    if (std::abs(sum - 1.0) > 1e-6)
      throw std::invalid_argument(fmt::format("p_stick + p_bounce + p_break at node {} = {} instead of 1", i, sum));
  }
}

// The corners of the cell enclosing a query with a non-zero weight (prod_k w_k), in the order of the
// interpolation sum (bit k of the corner number: upper node along the k-th present axis).
struct Corners {
  static constexpr std::size_t kMax = std::size_t{1} << kOutcomeAxisCount;
  std::array<std::size_t, kMax> i;  // the first `count` are set (not zeroed: 1 KB per query)
  std::array<double, kMax> w;
  std::size_t count = 0;
  bool clamped = false;
};

// The 8 corners of a table of the three required axes (the lookup of before the optional axes, unchanged).
void corners3(const OutcomeTable& t, const std::array<AxisPos, kOutcomeAxisCount>& pos, Corners& r) {
  const AxisPos &pv = pos[0], &p1 = pos[1], &p2 = pos[2];
  const std::size_t n1 = t.axes[1].size(), n2 = t.axes[2].size();
  for (int c = 0; c < 8; ++c) {
    const int bv = c & 1, b1 = (c >> 1) & 1, b2 = (c >> 2) & 1;
    const double w = (bv ? pv.w : 1.0 - pv.w) * (b1 ? p1.w : 1.0 - p1.w) * (b2 ? p2.w : 1.0 - p2.w);
    if (w == 0.0) continue;
    r.i[r.count] = ((pv.lo + static_cast<std::size_t>(bv)) * n1 + p1.lo + static_cast<std::size_t>(b1)) * n2 + p2.lo +
                   static_cast<std::size_t>(b2);
    r.w[r.count++] = w;
  }
}

// The 2^m corners over the m present axes `present` (in order), weights multiplied axis by axis.
void corners_n(const OutcomeTable& t, const std::array<AxisPos, kOutcomeAxisCount>& pos,
               const std::array<std::size_t, kOutcomeAxisCount>& present, std::size_t m, Corners& r) {
  std::array<std::size_t, kOutcomeAxisCount> stride{};
  std::size_t s = 1;  // row-major strides of the present axes
  for (std::size_t a = m; a-- > 0;) {
    stride[a] = s;
    s *= t.axes[present[a]].size();
  }
  for (std::size_t c = 0; c < (std::size_t{1} << m); ++c) {
    double w = 1.0;
    std::size_t i = 0;
    for (std::size_t a = 0; a < m; ++a) {
      const bool up = (c >> a) & 1U;
      w = a == 0 ? (up ? pos[a].w : 1.0 - pos[a].w) : w * (up ? pos[a].w : 1.0 - pos[a].w);
      i += (pos[a].lo + static_cast<std::size_t>(up)) * stride[a];
    }
    if (w == 0.0) continue;
    r.i[r.count] = i;
    r.w[r.count++] = w;
  }
}

// The pair is ordered by diameter (partner 1 the smaller), its charge with it.
Corners corners_of(const OutcomeTable& t, const OutcomeQuery& q) {
  Corners r;
  const bool swap = q.d_j < q.d_i;
  std::array<AxisPos, kOutcomeAxisCount> pos{};
  std::array<std::size_t, kOutcomeAxisCount> present = {kSpeedAxis, kDiameter1Axis, kDiameter2Axis};
  pos[0] = locate_log(t.axes[kSpeedAxis], q.speed, r.clamped);
  pos[1] = locate_log(t.axes[kDiameter1Axis], swap ? q.d_j : q.d_i, r.clamped);
  pos[2] = locate_log(t.axes[kDiameter2Axis], swap ? q.d_i : q.d_j, r.clamped);
  std::size_t m = kRequiredOutcomeAxes;
  if (t.has_axis(kCharge1Axis)) {
    pos[m] = locate_linear(t.axes[kCharge1Axis], swap ? q.sigma_j : q.sigma_i, r.clamped);
    present[m++] = kCharge1Axis;
    pos[m] = locate_linear(t.axes[kCharge2Axis], swap ? q.sigma_i : q.sigma_j, r.clamped);
    present[m++] = kCharge2Axis;
  }
  if (t.has_axis(kPermittivityAxis)) {
    pos[m] = locate_log(t.axes[kPermittivityAxis], q.permittivity, r.clamped);
    present[m++] = kPermittivityAxis;
  }
  if (t.has_primary_radii()) {
    pos[m] = locate_log(t.axes[kPrimaryRadius1Axis], swap ? q.rp_j : q.rp_i, r.clamped);
    present[m++] = kPrimaryRadius1Axis;
    pos[m] = locate_log(t.axes[kPrimaryRadius2Axis], swap ? q.rp_i : q.rp_j, r.clamped);
    present[m++] = kPrimaryRadius2Axis;
  }
  if (m == kRequiredOutcomeAxes)
    corners3(t, pos, r);
  else
    corners_n(t, pos, present, m, r);
  return r;
}

// The bin edges of the fragment mass distribution: 0 = e_0 < ... < e_B = 1, 1 <= B <= kMaxFragmentBins.
void check_fragment_edges(const std::vector<double>& e) {
  if (e.size() < 2 || e.size() > kMaxFragmentBins + 1)
    throw std::invalid_argument(fmt::format("variable '{}' has {} values: 2 to {} bin edges expected", kFragmentEdges,
                                            e.size(), kMaxFragmentBins + 1));
  if (e.front() != 0.0 || e.back() != 1.0)
    throw std::invalid_argument(fmt::format("variable '{}' runs from {} to {}: the edges of m / M run from 0 to 1",
                                            kFragmentEdges, e.front(), e.back()));
  for (std::size_t k = 1; k < e.size(); ++k)
    if (!(e[k] > e[k - 1]))
      throw std::invalid_argument(fmt::format("variable '{}' is not strictly increasing at value {} ({} after {})",
                                              kFragmentEdges, k, e[k], e[k - 1]));
}

// The distribution at node i (P_break > 0): h_b, mu_b >= 0, h_b > 0 iff mu_b > 0, sum mu_b = 1, the
// mean fraction mu_b / h_b within its bin, sum h_b >= 2 (and = N_f when the table has `fragments`).
void check_fragment_node(const OutcomeTable& t, std::size_t i) {
  const std::size_t nb = t.fragment_bins();
  const auto& [nn, mn] = kFragmentDistribution;
  double sum_h = 0.0, sum_mu = 0.0;
  for (std::size_t b = 0; b < nb; ++b) {
    const double h = t.fragment_number[i * nb + b], mu = t.fragment_mass[i * nb + b];
    if (!(h >= 0.0 && std::isfinite(h)) || !(mu >= 0.0 && std::isfinite(mu)) || ((h > 0.0) != (mu > 0.0)))
      throw std::invalid_argument(fmt::format("{} = {} and {} = {} at node {} bin {} where p_break > 0: both finite, "
                                              ">= 0, and zero together",
                                              nn, h, mn, mu, i, b));
    if (h > 0.0 && !(mu / h >= t.fragment_edges[b] - 1e-9 && mu / h <= t.fragment_edges[b + 1] + 1e-9))
      throw std::invalid_argument(fmt::format("{} / {} at node {} bin {} = {}: a fragment's mean mass fraction outside "
                                              "its bin [{}, {}]",
                                              mn, nn, i, b, mu / h, t.fragment_edges[b], t.fragment_edges[b + 1]));
    sum_h += h;
    sum_mu += mu;
  }
  if (std::abs(sum_mu - 1.0) > 1e-6)
    throw std::invalid_argument(fmt::format("{} at node {} sums to {} over the bins instead of 1", mn, i, sum_mu));
  if (!(sum_h >= 2.0 - 1e-9))
    throw std::invalid_argument(
        fmt::format("{} at node {} sums to {}: a pair that breaks has at least 2 fragments", nn, i, sum_h));
  if (!t.fragments.empty() && std::abs(sum_h - t.fragments[i]) > 1e-6 * t.fragments[i])
    throw std::invalid_argument(fmt::format("{} at node {} sums to {}, but {} = {}", nn, i, sum_h,
                                            kOutcomeFragmentStats[0], t.fragments[i]));
}

// Reads the optional fragment mass distribution of `d` into t (both variables and the edges, or none).
void read_fragment_distribution(const io::Dataset& d, OutcomeTable& t, std::vector<std::string> dims) {
  if (!d.find(kFragmentEdges) && !d.find(kFragmentDistribution[0]) && !d.find(kFragmentDistribution[1])) return;
  t.fragment_edges = values_of(variable(d, kFragmentEdges, {kFragmentEdgeDim}, "1"));
  check_fragment_edges(t.fragment_edges);
  dims.emplace_back(kFragmentBinDim);
  t.fragment_number = values_of(variable(d, kFragmentDistribution[0], dims, "1"));
  t.fragment_mass = values_of(variable(d, kFragmentDistribution[1], dims, "1"));
  if (t.fragment_number.size() != t.nodes() * t.fragment_bins())
    throw std::invalid_argument(fmt::format("variable '{}' has {} values: {} nodes x {} bins (the edges) expected",
                                            kFragmentDistribution[0], t.fragment_number.size(), t.nodes(),
                                            t.fragment_bins()));
}

// The distribution given a break at the corners c: weights W_c P_break,c (outcome_table.hpp).
void interpolate_fragment_bins(const OutcomeTable& t, const Corners& c, FragmentStats& f) {
  const std::size_t nb = t.fragment_bins();
  double sw = 0.0;
  f.bins = nb;
  for (std::size_t k = 0; k < c.count; ++k) {
    const double a = c.w[k] * t.p_break[c.i[k]];
    if (!(a > 0.0)) continue;  // nodes without breaks hold no distribution (may be NaN)
    sw += a;
    for (std::size_t b = 0; b < nb; ++b) {
      f.bin_number[b] += a * t.fragment_number[c.i[k] * nb + b];
      f.bin_mass[b] += a * t.fragment_mass[c.i[k] * nb + b];
    }
  }
  double n = 0.0;
  for (std::size_t b = 0; b < nb; ++b) {
    f.bin_number[b] /= sw;
    f.bin_mass[b] /= sw;
    n += f.bin_number[b];
  }
  f.number = n;
}

// Fragment statistics at the nodes with P_break > 0: present (or the distribution), N_f >= 2 and
// 1/N_f <= f_L < 1; the distribution's checks.
void check_fragments(const OutcomeTable& t) {
  for (std::size_t i = 0; i < t.p_break.size(); ++i) {
    if (!(t.p_break[i] > 0.0)) continue;
    if (t.fragment_bins() > 0) check_fragment_node(t, i);
    if (t.fragments.empty() && t.fragment_bins() > 0) continue;  // the distribution stands for them
    if (t.fragments.empty())
      throw std::invalid_argument(fmt::format("p_break at node {} = {} > 0, but no variable '{}' ({})", i,
                                              t.p_break[i], kOutcomeFragmentStats[0], kOutcomeFragmentMeanings[0]));
    const double nf = t.fragments[i], fl = t.largest_fraction[i];
    if (!(nf >= 2.0) || !std::isfinite(nf))
      throw std::invalid_argument(
          fmt::format("{} at node {} = {} where p_break > 0: a pair that breaks has at least 2 fragments",
                      kOutcomeFragmentStats[0], i, nf));
    if (!(fl >= 1.0 / nf && fl < 1.0))
      throw std::invalid_argument(fmt::format("{} at node {} = {} where p_break > 0: outside [1/{} = {:.6g}, 1)",
                                              kOutcomeFragmentStats[1], i, fl, kOutcomeFragmentStats[0], 1.0 / nf));
  }
}

}  // namespace

OutcomeProbabilities OutcomeTable::at(const OutcomeQuery& q) const {
  OutcomeProbabilities r;
  const Corners c = corners_of(*this, q);
  r.clamped = c.clamped;
  for (std::size_t k = 0; k < c.count; ++k) {
    r.stick += c.w[k] * p_stick[c.i[k]];
    r.bounce += c.w[k] * p_bounce[c.i[k]];
    r.brk += c.w[k] * p_break[c.i[k]];
  }
  return r;
}

FragmentStats OutcomeTable::fragments_at(const OutcomeQuery& q) const {
  if (fragment_bins() > 0) {
    FragmentStats f;
    const Corners c = corners_of(*this, q);
    interpolate_fragment_bins(*this, c, f);
    if (!(f.number > 0.0)) return {};  // no node of the cell broke
    return f;
  }
  if (fragments.empty()) return {};
  const Corners c = corners_of(*this, q);
  double sw = 0.0, sn = 0.0, sf = 0.0;
  for (std::size_t k = 0; k < c.count; ++k) {
    const double a = c.w[k] * p_break[c.i[k]];
    if (!(a > 0.0)) continue;  // nodes without breaks hold no statistics (may be NaN)
    sw += a;
    sn += a * fragments[c.i[k]];
    sf += a * largest_fraction[c.i[k]];
  }
  if (!(sw > 0.0)) return {};
  return {sn / sw, sf / sw};
}

std::vector<std::string> OutcomeTable::dimensions() const {
  std::vector<std::string> dims;
  for (std::size_t k = 0; k < kOutcomeAxisCount; ++k)
    if (has_axis(k)) dims.emplace_back(kOutcomeAxes[k]);
  return dims;
}

namespace {

// The number of global attribute `name` (NaN when absent); std::invalid_argument when it is not a number.
double number_attribute(const io::Dataset& d, const char* name) {
  if (!d.attributes.contains(name)) return std::nan("");
  const auto& a = d.attributes[name];
  if (a.is_number()) return a.get<double>();
  if (a.is_array() && a.size() == 1 && a[0].is_number()) return a[0].get<double>();
  throw std::invalid_argument(fmt::format("attribute '{}' is not a number", name));
}

// The pair of attributes (a, b): both or neither; each in its range.
void check_attribute_pair(double a, double b, const char* na, const char* nb) {
  if (std::isnan(a) != std::isnan(b))
    throw std::invalid_argument(fmt::format("attribute '{}' without '{}'", std::isnan(a) ? nb : na, std::isnan(a) ? na : nb));
}

// The fractal law and launch-gap attributes (outcome_table.hpp), checked.
void read_table_attributes(const io::Dataset& d, OutcomeTable& t) {
  const double df = number_attribute(d, kFractalDimensionAttribute), kf = number_attribute(d, kFractalPrefactorAttribute);
  check_attribute_pair(df, kf, kFractalDimensionAttribute, kFractalPrefactorAttribute);
  if (!std::isnan(df)) {
    if (!(df > 1.0 && df <= 3.0) || !(kf > 0.0))
      throw std::invalid_argument(fmt::format("attributes '{}' = {} and '{}' = {}: D_f in (1, 3] and k_f > 0 expected",
                                              kFractalDimensionAttribute, df, kFractalPrefactorAttribute, kf));
    t.fractal_dimension = df;
    t.fractal_prefactor = kf;
    if (d.attributes.contains(kFractalLawAttribute) && d.attributes[kFractalLawAttribute].is_string())
      t.fractal_law = d.attributes[kFractalLawAttribute].get<std::string>();
  }
  const double g = number_attribute(d, kLaunchGapAttribute), k0 = number_attribute(d, kMediumPermittivityAttribute);
  check_attribute_pair(g, k0, kLaunchGapAttribute, kMediumPermittivityAttribute);
  if (!std::isnan(g)) {
    if (!(g > 0.0) || !(k0 > 0.0))
      throw std::invalid_argument(fmt::format("attributes '{}' = {} and '{}' = {}: both positive expected",
                                              kLaunchGapAttribute, g, kMediumPermittivityAttribute, k0));
    t.launch_gap = g;
    t.medium_permittivity = k0;
  }
}

}  // namespace

OutcomeTable outcome_table_from_dataset(const io::Dataset& d) {
  OutcomeTable t;
  for (std::size_t k = 0; k < kOutcomeAxisCount; ++k) {
    if (k >= kRequiredOutcomeAxes && !d.find(kOutcomeAxes[k])) continue;  // an absent optional axis
    t.axes[k] = values_of(variable(d, kOutcomeAxes[k], {kOutcomeAxes[k]}, kOutcomeAxisUnits[k]));
    check_axis(k, t.axes[k]);
  }
  if (t.has_axis(kCharge1Axis) != t.has_axis(kCharge2Axis))
    throw std::invalid_argument(fmt::format("axis '{}' without axis '{}': a charged table has both",
                                            kOutcomeAxes[t.has_axis(kCharge1Axis) ? kCharge1Axis : kCharge2Axis],
                                            kOutcomeAxes[t.has_axis(kCharge1Axis) ? kCharge2Axis : kCharge1Axis]));
  if (t.has_axis(kPrimaryRadius1Axis) != t.has_axis(kPrimaryRadius2Axis))
    throw std::invalid_argument(fmt::format("axis '{}' without axis '{}': a table over primary radii has both",
                                            kOutcomeAxes[t.has_primary_radii() ? kPrimaryRadius1Axis : kPrimaryRadius2Axis],
                                            kOutcomeAxes[t.has_primary_radii() ? kPrimaryRadius2Axis : kPrimaryRadius1Axis]));
  const std::vector<std::string> dims = t.dimensions();
  t.p_stick = values_of(variable(d, kOutcomeProbabilities[0], dims, "1"));
  t.p_bounce = values_of(variable(d, kOutcomeProbabilities[1], dims, "1"));
  t.p_break = values_of(variable(d, kOutcomeProbabilities[2], dims, "1"));
  check_probabilities(t);
  if (d.find(kOutcomeFragmentStats[0]) || d.find(kOutcomeFragmentStats[1])) {  // both or neither
    t.fragments = values_of(variable(d, kOutcomeFragmentStats[0], dims, "1"));
    t.largest_fraction = values_of(variable(d, kOutcomeFragmentStats[1], dims, "1"));
  }
  read_fragment_distribution(d, t, dims);
  check_fragments(t);
  if (d.attributes.contains("provenance") && d.attributes["provenance"].is_string())
    t.provenance = d.attributes["provenance"].get<std::string>();
  read_table_attributes(d, t);
  return t;
}

io::Dataset outcome_table_dataset(const OutcomeTable& t) {
  io::Dataset d;
  for (std::size_t k = 0; k < kOutcomeAxisCount; ++k) {
    if (!t.has_axis(k)) continue;
    d.add_dim(kOutcomeAxes[k], t.axes[k].size());
    d.add(kOutcomeAxes[k], {kOutcomeAxes[k]}, kOutcomeAxisUnits[k], kOutcomeAxisMeanings[k], t.axes[k]);
  }
  const std::vector<std::string> dims = t.dimensions();
  d.add(kOutcomeProbabilities[0], dims, "1", "probability that the pair sticks", t.p_stick);
  d.add(kOutcomeProbabilities[1], dims, "1", "probability that the pair bounces", t.p_bounce);
  d.add(kOutcomeProbabilities[2], dims, "1", "probability that the pair breaks", t.p_break);
  if (!t.fragments.empty()) {
    d.add(kOutcomeFragmentStats[0], dims, "1", kOutcomeFragmentMeanings[0], t.fragments);
    d.add(kOutcomeFragmentStats[1], dims, "1", kOutcomeFragmentMeanings[1], t.largest_fraction);
  }
  if (t.fragment_bins() > 0) {
    d.add_dim(kFragmentEdgeDim, t.fragment_edges.size());
    d.add_dim(kFragmentBinDim, t.fragment_bins());
    d.add(kFragmentEdges, {kFragmentEdgeDim}, "1", kFragmentEdgesMeaning, t.fragment_edges);
    std::vector<std::string> bin_dims = dims;
    bin_dims.emplace_back(kFragmentBinDim);
    d.add(kFragmentDistribution[0], bin_dims, "1", kFragmentDistributionMeanings[0], t.fragment_number);
    d.add(kFragmentDistribution[1], bin_dims, "1", kFragmentDistributionMeanings[1], t.fragment_mass);
  }
  if (!t.provenance.empty()) d.attributes["provenance"] = t.provenance;
  if (t.has_fractal_law()) {
    d.attributes[kFractalDimensionAttribute] = t.fractal_dimension;
    d.attributes[kFractalPrefactorAttribute] = t.fractal_prefactor;
    if (!t.fractal_law.empty()) d.attributes[kFractalLawAttribute] = t.fractal_law;
  }
  if (t.has_launch_gap()) {
    d.attributes[kLaunchGapAttribute] = t.launch_gap;
    d.attributes[kMediumPermittivityAttribute] = t.medium_permittivity;
  }
  return d;
}

OutcomeTable load_outcome_table(const std::filesystem::path& file) {
  OutcomeTable t = outcome_table_from_dataset(io::read_netcdf(file));
  t.source = file.string();
  return t;
}

}  // namespace agglo::acoustics
