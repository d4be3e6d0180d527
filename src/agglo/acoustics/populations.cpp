#include "agglo/acoustics/populations.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"

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
