#include "agglo/impact/breakup.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/io/ensemble_stats.hpp"

namespace agglo::impact {

void wilson_interval(int k, int n, double& lo, double& hi) {
  if (n <= 0) {
    lo = 0.0;
    hi = 1.0;
    return;
  }
  const double z = 1.96, p = static_cast<double>(k) / n, z2n = z * z / n;
  const double centre = (p + 0.5 * z2n) / (1.0 + z2n);
  const double half = z * std::sqrt(p * (1.0 - p) / n + 0.25 * z2n / n) / (1.0 + z2n);
  lo = std::max(0.0, centre - half);
  hi = std::min(1.0, centre + half);
}

double first_crossing(const std::vector<BreakupPoint>& pts, double level) {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (pts[i].p < level) continue;
    if (i == 0) return pts[0].speed;
    const auto& a = pts[i - 1];
    const auto& b = pts[i];
    return a.speed + (b.speed - a.speed) * (level - a.p) / (b.p - a.p);
  }
  return -1.0;
}

std::vector<ImpactJob> breakup_jobs(const BreakupSpec& spec, double offset_radii) {
  std::vector<double> speeds = spec.speeds;
  std::sort(speeds.begin(), speeds.end());
  const int m = spec.samples, n = spec.orientations;
  std::vector<ImpactJob> jobs;
  for (double v : speeds)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < m; ++k)
        jobs.push_back(
            {v, m == 1 ? offset_radii : offset_radii + spec.offset_spread * (2.0 * (k + 0.5) / m - 1.0), j, n});
  return jobs;
}

BreakupResult breakup_probability(const BreakupSpec& spec, double offset_radii, const ImpactBatch& run_batch) {
  BreakupResult res;
  const std::vector<ImpactJob> jobs = breakup_jobs(spec, offset_radii);
  for (std::size_t k = 0; k < static_cast<std::size_t>(spec.samples); ++k) res.offsets.push_back(jobs[k].offset_radii);
  res.orientations = spec.orientations;
  const std::size_t m = static_cast<std::size_t>(spec.samples) * static_cast<std::size_t>(spec.orientations);
  std::vector<double> speeds;
  for (std::size_t j = 0; j < jobs.size(); j += m) speeds.push_back(jobs[j].speed);
  res.outcomes = run_batch(jobs);
  for (std::size_t s = 0; s < speeds.size(); ++s) {
    BreakupPoint pt;
    pt.speed = speeds[s];
    std::vector<double> damage, largest;
    for (std::size_t k = 0; k < m; ++k) {
      const auto& o = res.outcomes[s * m + k];
      ++pt.runs;
      pt.broken += o.broken ? 1 : 0;
      pt.undecided += o.undecided ? 1 : 0;
      damage.push_back(o.breakage.damage_ratio);
      largest.push_back(o.breakage.largest_fraction);
    }
    const auto d = io::mean_stderr(damage), l = io::mean_stderr(largest);
    pt.damage = d.mean, pt.damage_se = d.standard_error;
    pt.largest = l.mean, pt.largest_se = l.standard_error;
    pt.p = static_cast<double>(pt.broken) / pt.runs;
    wilson_interval(pt.broken, pt.runs, pt.ci_lo, pt.ci_hi);
    res.points.push_back(pt);
  }
  res.v10 = first_crossing(res.points, 0.1);
  res.v50 = first_crossing(res.points, 0.5);
  res.v90 = first_crossing(res.points, 0.9);
  return res;
}

}  // namespace agglo::impact
