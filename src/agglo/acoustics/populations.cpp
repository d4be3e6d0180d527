#include "agglo/acoustics/populations.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"
#include "agglo/core/rng.hpp"

namespace agglo::acoustics {

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

double normal_quantile(double q) {
  double lo = -40.0, hi = 40.0;
  for (int it = 0; it < 200 && hi - lo > 1e-14; ++it) {
    const double mid = 0.5 * (lo + hi);
    (normal_cdf(mid) < q ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

namespace {
struct Draft {
  double d = 0.0;    // diameter (or volume if by_volume)
  double w = 0.0;    // real number represented (before rounding)
};
}  // namespace

SampledPopulation sample_population(const PopulationSpec& s, int index, const Domain& dom, std::uint64_t seed,
                                    const Gas& gas, const Sound& sound, SampleSet& p) {
  using constants::pi;
  const double V = dom.volume();
  const double Ntot = s.number_concentration * V;
  std::vector<double> diam, num;  // diameter and real number per sample
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
      const int K = s.bins;
      const double ls = std::log(s.geometric_std);
      const double zlo = -3.5, zhi = 3.5;
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
  SampledPopulation out;
  out.first = p.size();
  out.real_number = Ntot;
  double cum = 0.0, cum_rounded = 0.0;  // running real number and its rounding (conserving rounding)
  for (std::size_t m = 0; m < diam.size(); ++m) {
    CounterRng rng(seed, 0x9000000000ULL + static_cast<std::uint64_t>(index), m);
    const double x = rng.uniform() * dom.L[0], y = rng.uniform() * dom.L[1], z = rng.uniform() * dom.L[2];
    const double vol = pi * diam[m] * diam[m] * diam[m] / 6.0;
    double w;
    if (s.conserving_rounding) {
      cum += num[m];
      w = std::max(1.0, std::round(cum) - cum_rounded);
      cum_rounded += w;
    } else {
      w = std::max(1.0, std::round(num[m]));
    }
    const bool solid = s.phase == Phase::solid;
    const std::size_t i = p.add(x, y, z, solid ? vol : 0.0, solid ? 0.0 : vol, s.density * vol, w, index, gas, sound);
    p.id[i] = i;
    out.weight_sum += w;
  }
  out.count = diam.size();
  return out;
}

}  // namespace agglo::acoustics
