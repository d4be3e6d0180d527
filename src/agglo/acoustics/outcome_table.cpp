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

bool off_node(double x, double node) { return !(std::abs(x - node) <= kOnNode * node); }

AxisPos locate_log(const std::vector<double>& a, double x, bool& clamped) {
  if (a.size() == 1) {
    if (off_node(x, a[0])) clamped = true;
    return {};
  }
  if (!(x > a.front())) {  // also x <= 0 and NaN
    if (off_node(x, a.front())) clamped = true;
    return {};
  }
  if (x >= a.back()) {
    if (off_node(x, a.back())) clamped = true;
    return {a.size() - 2, 1.0};
  }
  const std::size_t hi = static_cast<std::size_t>(std::upper_bound(a.begin(), a.end(), x) - a.begin());
  const std::size_t lo = hi - 1;
  return {lo, std::log(x / a[lo]) / std::log(a[hi] / a[lo])};
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

void check_axis(const char* name, const std::vector<double>& a) {
  if (a.empty()) throw std::invalid_argument(fmt::format("axis '{}' is empty", name));
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!(a[k] > 0.0) || !std::isfinite(a[k]))
      throw std::invalid_argument(fmt::format("axis '{}' value {} = {} is not a positive number", name, k, a[k]));
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
// interpolation sum.
struct Corners {
  std::array<std::size_t, 8> i{};
  std::array<double, 8> w{};
  std::size_t count = 0;
  bool clamped = false;
};

Corners corners_of(const OutcomeTable& t, double v, double di, double dj) {
  Corners r;
  const AxisPos pv = locate_log(t.axes[0], v, r.clamped);
  const AxisPos p1 = locate_log(t.axes[1], std::min(di, dj), r.clamped);
  const AxisPos p2 = locate_log(t.axes[2], std::max(di, dj), r.clamped);
  for (int c = 0; c < 8; ++c) {
    const int bv = c & 1, b1 = (c >> 1) & 1, b2 = (c >> 2) & 1;
    const double w = (bv ? pv.w : 1.0 - pv.w) * (b1 ? p1.w : 1.0 - p1.w) * (b2 ? p2.w : 1.0 - p2.w);
    if (w == 0.0) continue;
    r.i[r.count] = t.index(pv.lo + static_cast<std::size_t>(bv), p1.lo + static_cast<std::size_t>(b1),
                           p2.lo + static_cast<std::size_t>(b2));
    r.w[r.count++] = w;
  }
  return r;
}

// Fragment statistics at the nodes with P_break > 0: present, N_f >= 2 and 1/N_f <= f_L < 1.
void check_fragments(const OutcomeTable& t) {
  for (std::size_t i = 0; i < t.p_break.size(); ++i) {
    if (!(t.p_break[i] > 0.0)) continue;
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

OutcomeProbabilities OutcomeTable::at(double v, double di, double dj) const {
  OutcomeProbabilities r;
  const Corners c = corners_of(*this, v, di, dj);
  r.clamped = c.clamped;
  for (std::size_t k = 0; k < c.count; ++k) {
    r.stick += c.w[k] * p_stick[c.i[k]];
    r.bounce += c.w[k] * p_bounce[c.i[k]];
    r.brk += c.w[k] * p_break[c.i[k]];
  }
  return r;
}

FragmentStats OutcomeTable::fragments_at(double v, double di, double dj) const {
  if (fragments.empty()) return {};
  const Corners c = corners_of(*this, v, di, dj);
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

OutcomeTable outcome_table_from_dataset(const io::Dataset& d) {
  OutcomeTable t;
  for (std::size_t k = 0; k < 3; ++k) {
    t.axes[k] = values_of(variable(d, kOutcomeAxes[k], {kOutcomeAxes[k]}, kOutcomeAxisUnits[k]));
    check_axis(kOutcomeAxes[k], t.axes[k]);
  }
  const std::vector<std::string> dims(kOutcomeAxes.begin(), kOutcomeAxes.end());
  t.p_stick = values_of(variable(d, kOutcomeProbabilities[0], dims, "1"));
  t.p_bounce = values_of(variable(d, kOutcomeProbabilities[1], dims, "1"));
  t.p_break = values_of(variable(d, kOutcomeProbabilities[2], dims, "1"));
  check_probabilities(t);
  if (d.find(kOutcomeFragmentStats[0]) || d.find(kOutcomeFragmentStats[1])) {  // both or neither
    t.fragments = values_of(variable(d, kOutcomeFragmentStats[0], dims, "1"));
    t.largest_fraction = values_of(variable(d, kOutcomeFragmentStats[1], dims, "1"));
  }
  check_fragments(t);
  if (d.attributes.contains("provenance") && d.attributes["provenance"].is_string())
    t.provenance = d.attributes["provenance"].get<std::string>();
  return t;
}

io::Dataset outcome_table_dataset(const OutcomeTable& t) {
  io::Dataset d;
  static constexpr std::array<const char*, 3> axis_meaning = {
      "normal relative speed at contact", "diameter of the smaller partner", "diameter of the larger partner"};
  for (std::size_t k = 0; k < 3; ++k) {
    d.add_dim(kOutcomeAxes[k], t.axes[k].size());
    d.add(kOutcomeAxes[k], {kOutcomeAxes[k]}, kOutcomeAxisUnits[k], axis_meaning[k], t.axes[k]);
  }
  const std::vector<std::string> dims(kOutcomeAxes.begin(), kOutcomeAxes.end());
  d.add(kOutcomeProbabilities[0], dims, "1", "probability that the pair sticks", t.p_stick);
  d.add(kOutcomeProbabilities[1], dims, "1", "probability that the pair bounces", t.p_bounce);
  d.add(kOutcomeProbabilities[2], dims, "1", "probability that the pair breaks", t.p_break);
  if (!t.fragments.empty()) {
    d.add(kOutcomeFragmentStats[0], dims, "1", kOutcomeFragmentMeanings[0], t.fragments);
    d.add(kOutcomeFragmentStats[1], dims, "1", kOutcomeFragmentMeanings[1], t.largest_fraction);
  }
  if (!t.provenance.empty()) d.attributes["provenance"] = t.provenance;
  return d;
}

OutcomeTable load_outcome_table(const std::filesystem::path& file) {
  OutcomeTable t = outcome_table_from_dataset(io::read_netcdf(file));
  t.source = file.string();
  return t;
}

}  // namespace agglo::acoustics
