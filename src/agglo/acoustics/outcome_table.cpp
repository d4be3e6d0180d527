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

}  // namespace

OutcomeProbabilities OutcomeTable::at(double v, double di, double dj) const {
  OutcomeProbabilities r;
  const AxisPos pv = locate_log(axes[0], v, r.clamped);
  const AxisPos p1 = locate_log(axes[1], std::min(di, dj), r.clamped);
  const AxisPos p2 = locate_log(axes[2], std::max(di, dj), r.clamped);
  for (int c = 0; c < 8; ++c) {
    const int bv = c & 1, b1 = (c >> 1) & 1, b2 = (c >> 2) & 1;
    const double w = (bv ? pv.w : 1.0 - pv.w) * (b1 ? p1.w : 1.0 - p1.w) * (b2 ? p2.w : 1.0 - p2.w);
    if (w == 0.0) continue;
    const std::size_t i = index(pv.lo + static_cast<std::size_t>(bv), p1.lo + static_cast<std::size_t>(b1),
                                p2.lo + static_cast<std::size_t>(b2));
    r.stick += w * p_stick[i];
    r.bounce += w * p_bounce[i];
    r.brk += w * p_break[i];
  }
  return r;
}

double OutcomeTable::max_break() const {
  return p_break.empty() ? 0.0 : *std::max_element(p_break.begin(), p_break.end());
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
  if (!t.provenance.empty()) d.attributes["provenance"] = t.provenance;
  return d;
}

OutcomeTable load_outcome_table(const std::filesystem::path& file) {
  OutcomeTable t = outcome_table_from_dataset(io::read_netcdf(file));
  t.source = file.string();
  return t;
}

}  // namespace agglo::acoustics
