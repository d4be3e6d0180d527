#include "agglo/acoustics/diagnostics.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

// Dead samples (w = 0) add exact zeros, so the sums need no branch.
Counts count(const SampleSet& p, double V) {
  Counts c;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double w = p.w[i], ph = p.phase_code[i];
    c.live_samples += w > 0.0 ? 1 : 0;
    c.n_total += w;
    c.n_phase[0] += ph == 0.0 ? w : 0.0;
    c.n_phase[1] += ph == 1.0 ? w : 0.0;
    c.n_phase[2] += ph == 2.0 ? w : 0.0;
    c.solid_volume += w * p.vol_s[i];
    c.liquid_volume += w * p.vol_l[i];
    c.mass += w * p.mass[i];
  }
  c.n_total /= V;
  for (double& x : c.n_phase) x /= V;
  c.solid_volume /= V;
  c.liquid_volume /= V;
  c.mass /= V;
  return c;
}

namespace {
// Adds sample i's mass w m to every cut its diameter and its settling measure pass. A sum that does not
// take the sample skips the add (adding +0 would leave it unchanged), so the sums are those of a loop
// adding w m or 0 to every cut.
inline void add_pm(PmMass& m, const std::array<double, 3>& limit, double wm, double d, double settling) {
  for (std::size_t k = 0; k < 3; ++k) {
    if (d < kPmCuts[k]) m.volume[k] += wm;
    if (settling < limit[k]) m.aerodynamic[k] += wm;
  }
}
}  // namespace

PmMass pm_mass(const SampleSet& p, double V, const Gas& g) {
  std::array<double, 3> limit{};  // rho_0 x^2 C_c(x): d_a < x iff rho_p d_v^2 C_c(d_v) is below it
  for (std::size_t k = 0; k < 3; ++k) limit[k] = kPmUnitDensity * kPmCuts[k] * kPmCuts[k] * g.slip_correction(kPmCuts[k]);
  PmMass m;
  if (p.structured()) {
    for (std::size_t i = 0; i < p.size(); ++i)
      add_pm(m, limit, p.w[i] * p.mass[i], p.volume_diameter(i), 6.0 * p.mass[i] * p.cc[i] / (constants::pi * p.dm[i]));
  } else {  // a sphere's volume diameter is its diameter d
    const double *w = p.w.data(), *mass = p.mass.data(), *d = p.d.data(), *rho = p.rho.data(), *cc = p.cc.data();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (w[i] > 0.0) add_pm(m, limit, w[i] * mass[i], d[i], rho[i] * d[i] * d[i] * cc[i]);
  }
  for (std::size_t k = 0; k < 3; ++k) {
    m.volume[k] /= V;
    m.aerodynamic[k] /= V;
  }
  return m;
}

double aerodynamic_diameter(const Gas& g, double dv, double rho_p) {
  const double a = dv * std::sqrt(rho_p * g.slip_correction(dv) / kPmUnitDensity);
  double da = dv * std::sqrt(rho_p / kPmUnitDensity);
  for (int it = 0; it < 60; ++it) {
    const double next = a / std::sqrt(g.slip_correction(da));
    const bool done = std::abs(next - da) <= 1e-13 * next;
    da = next;
    if (done) break;
  }
  return da;
}

PsdBins PsdBins::log_spaced(double dmin, double dmax, int k) {
  PsdBins b;
  for (int i = 0; i <= k; ++i) b.edges.push_back(dmin * std::pow(dmax / dmin, static_cast<double>(i) / k));
  return b;
}

int PsdBins::find(double d) const {
  if (d < edges.front() || d >= edges.back()) return -1;
  const auto it = std::upper_bound(edges.begin(), edges.end(), d);
  return static_cast<int>(it - edges.begin()) - 1;
}

std::array<std::vector<double>, 4> psd(const SampleSet& p, double V, const PsdBins& bins) {
  const std::size_t K = bins.edges.size() - 1;
  std::array<std::vector<double>, 4> out;
  for (auto& v : out) v.assign(K, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.w[i] <= 0.0) continue;
    const int b = bins.find(p.volume_diameter(i));
    if (b < 0) continue;
    out[static_cast<int>(p.phase(i))][b] += p.w[i];
    out[3][b] += p.w[i];
  }
  for (std::size_t b = 0; b < K; ++b) {
    const double dl = std::log10(bins.edges[b + 1] / bins.edges[b]);
    for (auto& v : out) v[b] /= V * dl;
  }
  return out;
}

}  // namespace agglo::acoustics
