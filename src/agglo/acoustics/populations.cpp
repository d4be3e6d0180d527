#include "agglo/acoustics/populations.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

namespace {
// Acklam's rational approximation of the standard normal quantile (relative error below 1.2e-9 on
// (0, 1)), polished by one Halley step on Phi(z) - q: a starting point, not a result.
double quantile_estimate(double q) {
  static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                                 1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                                 6.680131188771972e+01,  -1.328068155288572e+01};
  static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                                 -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                                 3.754408661907416e+00};
  const auto tail = [&](double r) {
    const double t = std::sqrt(-2.0 * std::log(r));
    return (((((c[0] * t + c[1]) * t + c[2]) * t + c[3]) * t + c[4]) * t + c[5]) /
           ((((d[0] * t + d[1]) * t + d[2]) * t + d[3]) * t + 1.0);
  };
  double z;
  if (q < 0.02425) {
    z = tail(q);
  } else if (q > 1.0 - 0.02425) {
    z = -tail(1.0 - q);
  } else {
    const double u = q - 0.5, r = u * u;
    z = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * u /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
  }
  const double e = normal_cdf(z) - q, pdf = std::exp(-0.5 * z * z) / std::sqrt(2.0 * constants::pi);
  const double step = e / pdf;
  return z - step / (1.0 + 0.5 * z * step);
}
}  // namespace

double normal_quantile_bisection(double q) {
  double lo = -40.0, hi = 40.0;
  for (int it = 0; it < 200 && hi - lo > 1e-14; ++it) {
    const double mid = 0.5 * (lo + hi);
    (normal_cdf(mid) < q ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

namespace {
// One end of the bracket of the root of Phi(x) = q around the estimate z: side -1 the lower end (Phi < q),
// +1 the upper end (Phi >= q). First z -+ delta; where Phi is flat at the scale of delta (the far tails,
// where Phi rounds to a few values) the distance grows 16-fold until the end holds and once more
// (checked too), so that the end lies well beyond the rounding of Phi near the root. NaN: none found.
constexpr double kNoBracketEnd = std::numeric_limits<double>::quiet_NaN();
double bracket_end(double z, double q, double delta, int side) {
  const auto holds = [&](double x) { return side < 0 ? normal_cdf(x) < q : !(normal_cdf(x) < q); };
  const double s = side;
  if (holds(z + s * delta)) return z + s * delta;
  for (double dd = 16.0 * delta; dd < 1.0; dd *= 16.0)
    if (holds(z + s * dd)) return holds(z + s * 16.0 * dd) ? z + s * 16.0 * dd : kNoBracketEnd;
  return kNoBracketEnd;
}
}  // namespace

// The bisection of normal_quantile_bisection, step for step: a midpoint at or below a (where
// Phi(a) < q was checked) goes to lo and one at or above b (Phi(b) >= q) to hi without evaluating Phi
// (Phi is increasing, and the bracket is wide enough against its rounding: 1e-14 (1 + |z|) around an
// estimate good to ~1e-15, i.e. >= 30 units in the last place of Phi near the root in the middle, wider
// where Phi is flat); only the midpoints inside [a, b] evaluate Phi, about 3 of the 53 (with the
// estimate's and the two checks' 6 in all; 13 with the former bracket 1e-12 (1 + |z|)).
double normal_quantile(double q) {
  double a = -40.0, b = 40.0;
  if (q > 0.0 && q < 1.0) {
    const double z = quantile_estimate(q);
    if (std::isfinite(z)) {
      const double delta = 1e-14 * (1.0 + std::abs(z));
      const double lo = bracket_end(z, q, delta, -1), hi = bracket_end(z, q, delta, 1);
      if (!std::isnan(lo) && !std::isnan(hi)) {
        a = lo;
        b = hi;
      }
    }
  }
  double lo = -40.0, hi = 40.0;
  for (int it = 0; it < 200 && hi - lo > 1e-14; ++it) {
    const double mid = 0.5 * (lo + hi);
    const bool below = mid <= a ? true : mid >= b ? false : normal_cdf(mid) < q;
    (below ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

namespace {
// Lognormal with equal weights: sample m at the quantile (m + 1/2)/n of the distribution within
// ln d_g +- range ln sigma_g, each standing for N_tot / n particles.
void draft_lognormal_equal(const PopulationSpec& s, double Ntot, std::vector<double>& diam, std::vector<double>& num) {
  const double ls = std::log(s.geometric_std), Flo = normal_cdf(-s.lognormal_range);
  const double Fhi = normal_cdf(s.lognormal_range);
  const long n = s.samples;
  for (long m = 0; m < n; ++m) {
    const double z = normal_quantile(Flo + (Fhi - Flo) * (static_cast<double>(m) + 0.5) / static_cast<double>(n));
    diam.push_back(s.geometric_mean_diameter * std::exp(z * ls));
    num.push_back(Ntot / static_cast<double>(n));
  }
}

// Diameter and real number (before rounding) of every sample of the population, in size order.
void draft(const PopulationSpec& s, double Ntot, std::vector<double>& diam, std::vector<double>& num) {
  using constants::pi;
  const long n = s.samples;
  switch (s.distribution) {
    case Distribution::monodisperse:
      for (long m = 0; m < n; ++m) {
        diam.push_back(s.diameter);
        num.push_back(Ntot / n);
      }
      break;
    case Distribution::exponential:
      for (long m = 0; m < n; ++m) {
        const double v = -s.mean_volume * std::log1p(-(m + 0.5) / n);
        diam.push_back(std::cbrt(6.0 * v / pi));
        num.push_back(Ntot / n);
      }
      break;
    case Distribution::lognormal: {
      if (s.lognormal_equal_weights) {
        draft_lognormal_equal(s, Ntot, diam, num);
        break;
      }
      const int K = s.bins;
      const double ls = std::log(s.geometric_std);
      const double zlo = -s.lognormal_range, zhi = s.lognormal_range;
      const double Ftot = normal_cdf(zhi) - normal_cdf(zlo);
      for (int k = 0; k < K; ++k) {
        const double za = zlo + (zhi - zlo) * k / K, zb = zlo + (zhi - zlo) * (k + 1) / K;
        const double Fa = normal_cdf(za), Fb = normal_cdf(zb);
        const long nk = n / K + (k < n % K ? 1 : 0);
        for (long m = 0; m < nk; ++m) {
          const double z = normal_quantile(Fa + (Fb - Fa) * (m + 0.5) / nk);
          diam.push_back(s.geometric_mean_diameter * std::exp(z * ls));
          num.push_back(Ntot * (Fb - Fa) / Ftot / nk);
        }
      }
      break;
    }
    case Distribution::table: {
      const std::size_t K = s.table_diameters.size();
      double fsum = 0.0;
      for (double f : s.table_fractions) fsum += f;
      for (std::size_t k = 0; k < K; ++k) {
        const long nk = n / static_cast<long>(K) + (static_cast<long>(k) < n % static_cast<long>(K) ? 1 : 0);
        for (long m = 0; m < nk; ++m) {
          diam.push_back(s.table_diameters[k]);
          num.push_back(Ntot * s.table_fractions[k] / fsum / nk);
        }
      }
      break;
    }
  }
}
}  // namespace

std::vector<StructureLaw> structure_laws_of(const std::vector<PopulationSpec>& pops) {
  std::vector<StructureLaw> laws;
  for (const PopulationSpec& s : pops) laws.push_back(s.structure);
  for (const StructureLaw& l : laws)
    if (l.fractal) return laws;
  return {};
}

SampledPopulation sample_population(const PopulationSpec& s, int index, const Domain& dom, std::uint64_t seed,
                                    const Gas& gas, const Sound& sound, SampleSet& p, const SamplingSettings& sampling) {
  const double Ntot = s.number_concentration * dom.volume();
  std::vector<double> diam, num;  // diameter and real number per sample
  draft(s, Ntot, diam, num);
  p.reserve(p.size() + diam.size());
  SampledPopulation out;
  out.first = p.size();
  out.real_number = Ntot;
  out.requested = diam.size();
  double cum = 0.0, cum_rounded = 0.0;  // running real number and its rounding (conserving rounding)
  for (std::size_t m = 0; m < diam.size(); ++m) {
    const double vol = constants::pi * diam[m] * diam[m] * diam[m] / 6.0;
    double w;
    if (s.conserving_rounding) {
      cum += num[m];
      w = std::max(1.0, std::round(cum) - cum_rounded);
      cum_rounded += w;
    } else {
      w = std::max(1.0, std::round(num[m]));
    }
    const bool solid = s.phase == Phase::solid;
    const std::size_t i = p.add(0.0, 0.0, 0.0, solid ? vol : 0.0, solid ? 0.0 : vol, s.density * vol, w, index, gas, sound);
    if (solid && s.structure.fractal) p.set_primaries(i, s.structure.primary_radius, gas, sound);
    if (p.carries_charge) {  // q = sigma pi d_v^2 (samples.hpp)
      const double dv = p.volume_diameter(i);
      p.q[i] = s.charge_density * constants::pi * dv * dv;
    }
    out.weight_sum += w;
  }
  out.clone_factor = clone_factor(static_cast<std::int64_t>(diam.size()), dom.num_cells(), sampling.min_samples_per_cell);
  out.count = split_into_clones(p, out.first, diam.size(), out.clone_factor);
  place_samples(p, out.first, out.count, sampling.placement, dom, seed, index);
  for (std::size_t i = out.first; i < out.first + out.count; ++i) p.id[i] = i;
  return out;
}

}  // namespace agglo::acoustics
