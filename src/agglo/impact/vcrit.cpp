#include "agglo/impact/vcrit.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::impact {

namespace {
std::vector<ImpactOutcome> run_all(const std::vector<double>& speeds, const RunFunction& run) {
  std::vector<ImpactOutcome> out(speeds.size());
  std::vector<std::exception_ptr> err(speeds.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t k = 0; k < static_cast<std::int64_t>(speeds.size()); ++k) {
    try {
      out[k] = run(speeds[k]);
    } catch (...) {
      err[k] = std::current_exception();
    }
  }
  for (auto& e : err)
    if (e) std::rethrow_exception(e);
  return out;
}
}  // namespace

VcritResult find_vcrit(const VcritSpec& spec, int parallel_runs, const RunFunction& run,
                       const std::function<void(double)>& progress) {
  VcritResult res;
  parallel_runs = std::max(parallel_runs, 2);
  std::vector<double> scan(spec.scan_points);
  for (int k = 0; k < spec.scan_points; ++k)
    scan[k] = spec.v_min + (spec.v_max - spec.v_min) * k / (spec.scan_points - 1);
  auto add = [&](const std::vector<ImpactOutcome>& o) { res.runs.insert(res.runs.end(), o.begin(), o.end()); };
  add(run_all(scan, run));
  auto sorted = [&]() {
    std::sort(res.runs.begin(), res.runs.end(), [](const auto& a, const auto& b) { return a.speed < b.speed; });
  };
  sorted();
  const double expected_rounds = std::log(std::max(1.0, (scan[1] - scan[0]) / spec.tolerance)) /
                                 std::log(parallel_runs + 1.0);
  if (progress) progress(0.0);
  for (;;) {
    // Highest non-breaking speed, and the lowest breaking speed above it.
    const ImpactOutcome* last_nb = nullptr;
    for (const auto& r : res.runs)
      if (!r.broken) last_nb = &r;
    if (!last_nb)
      throw NumericalError(fmt::format("vcrit: every speed from {} m/s breaks the agglomerate; lower vcrit.v_min",
                                       spec.v_min));
    auto it = std::find_if(res.runs.begin(), res.runs.end(), [&](const auto& r) { return r.speed > last_nb->speed; });
    if (it == res.runs.end())
      throw NumericalError(fmt::format("vcrit: no break-up up to {} m/s; raise vcrit.v_max", spec.v_max));
    res.lo = last_nb->speed;
    res.hi = it->speed;
    if (res.hi - res.lo <= spec.tolerance) break;
    std::vector<double> mid(parallel_runs);
    for (int k = 0; k < parallel_runs; ++k) mid[k] = res.lo + (res.hi - res.lo) * (k + 1) / (parallel_runs + 1);
    add(run_all(mid, run));
    sorted();
    ++res.rounds;
    if (progress) progress(std::min(0.99, res.rounds / std::max(1.0, expected_rounds)));
  }
  res.v_crit = res.hi;
  for (const auto& r : res.runs) {
    if (r.broken && r.speed < res.lo)
      res.warnings.push_back(fmt::format("non-monotonic: v = {:.6g} m/s breaks but v = {:.6g} m/s does not",
                                         r.speed, res.lo));
    if (r.undecided)
      res.warnings.push_back(fmt::format("undecided outcome at v = {:.6g} m/s (counted as not broken)", r.speed));
    if (!r.contact) res.warnings.push_back(fmt::format("no contact at v = {:.6g} m/s", r.speed));
  }
  return res;
}

}  // namespace agglo::impact
