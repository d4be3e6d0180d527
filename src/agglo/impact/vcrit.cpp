#include "agglo/impact/vcrit.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::impact {

namespace {

std::vector<double> scan_grid(const VcritSpec& spec) {
  std::vector<double> scan(spec.scan_points);
  for (int k = 0; k < spec.scan_points; ++k)
    scan[k] = spec.v_min + (spec.v_max - spec.v_min) * k / (spec.scan_points - 1);
  return scan;
}

// The event the bisection brackets: a break-up, or (sticking) an impact that does not stay. A run
// without contact counts as no event (and is warned about).
bool event(const VcritSpec& spec, const ImpactOutcome& r) {
  return spec.sticking ? r.contact && !stays(r) : r.broken;
}

// Sets the bracket from the highest speed without the event; true when it is narrow enough.
bool update_bracket(const VcritSpec& spec, VcritResult& res) {
  const ImpactOutcome* last_nb = nullptr;
  for (const auto& r : res.runs)
    if (!event(spec, r)) last_nb = &r;
  if (!last_nb)
    throw NumericalError(fmt::format("vcrit: every speed from {} m/s {}; lower the scan's lowest speed", spec.v_min,
                                     spec.sticking ? "rebounds" : "breaks the agglomerate"));
  auto it = std::find_if(res.runs.begin(), res.runs.end(), [&](const auto& r) { return r.speed > last_nb->speed; });
  if (it == res.runs.end())
    throw NumericalError(fmt::format("vcrit: {} up to {} m/s; raise the scan's highest speed",
                                     spec.sticking ? "every speed stays" : "no break-up", spec.v_max));
  res.lo = last_nb->speed;
  res.hi = it->speed;
  return res.hi - res.lo <= spec.tolerance;
}

void add_warnings(const VcritSpec& spec, VcritResult& res) {
  for (const auto& r : res.runs) {
    if (event(spec, r) && r.speed < res.lo)
      res.warnings.push_back(fmt::format("non-monotonic: v = {:.6g} m/s {} but v = {:.6g} m/s does not", r.speed,
                                         spec.sticking ? "rebounds" : "breaks", res.lo));
    if (r.undecided)
      res.warnings.push_back(fmt::format("undecided outcome at v = {:.6g} m/s (counted as not broken)", r.speed));
    if (!r.contact) res.warnings.push_back(fmt::format("no contact at v = {:.6g} m/s", r.speed));
  }
}

}  // namespace

bool stays(const ImpactOutcome& o) {
  if (!o.contact) return false;
  if (o.breakage.wall != WallOutcome::none) return o.breakage.wall == WallOutcome::stuck;
  // The agglomerate's primaries are the first n_agg particles, n_agg = the primaries of all fragments.
  int n_agg = 0;
  for (int s : o.breakage.fragment_sizes) n_agg += s;
  int last = -1;
  const std::vector<int>* with_last = nullptr;
  for (const auto& g : o.components)
    for (int k : g)
      if (k > last) {
        last = k;
        with_last = &g;
      }
  return with_last && last >= n_agg && with_last->front() < n_agg;  // components are sorted
}

VcritResult find_vcrit(const VcritSpec& spec, const SpeedBatch& run_batch, const std::function<void(double)>& progress) {
  VcritResult res;
  const int per_round = std::max(spec.points_per_round, 1);
  const std::vector<double> scan = scan_grid(spec);
  // top_down: highest speed first, stopping at the first without the event (the bracket's lower end).
  const StopRule stop = spec.top_down ? StopRule([&spec](const ImpactOutcome& r) { return !event(spec, r); })
                                      : StopRule();
  auto add = [&](std::vector<double> speeds) {
    if (spec.top_down) std::sort(speeds.begin(), speeds.end(), std::greater<>());
    const auto o = run_batch(speeds, stop);
    res.runs.insert(res.runs.end(), o.begin(), o.end());
    std::sort(res.runs.begin(), res.runs.end(), [](const auto& a, const auto& b) { return a.speed < b.speed; });
  };
  add(scan);
  const double expected_rounds =
      std::log(std::max(1.0, (scan[1] - scan[0]) / spec.tolerance)) / std::log(per_round + 1.0);
  if (progress) progress(0.0);
  while (!update_bracket(spec, res)) {
    std::vector<double> mid(per_round);
    for (int k = 0; k < per_round; ++k) mid[k] = res.lo + (res.hi - res.lo) * (k + 1) / (per_round + 1);
    // Below the spacing of doubles the midpoints no longer move inside the bracket: stop there.
    if (std::none_of(mid.begin(), mid.end(), [&](double v) { return v > res.lo && v < res.hi; })) {
      res.warnings.push_back(fmt::format("bracket [{:.17g}, {:.17g}] m/s cannot shrink further (floating-point "
                                         "resolution); stopped above the tolerance",
                                         res.lo, res.hi));
      break;
    }
    add(mid);
    ++res.rounds;
    if (progress) progress(std::min(0.99, res.rounds / std::max(1.0, expected_rounds)));
  }
  res.sticking = spec.sticking;
  res.v_crit = spec.sticking ? res.lo : res.hi;
  add_warnings(spec, res);
  return res;
}

}  // namespace agglo::impact
