#include "agglo/acoustics/kernels/brownian_partmc.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

namespace {
// PartMC 2.9.0's constants (header of brownian_partmc.hpp).
constexpr double kBoltzmann = 1.3806505e-23;  // [J/K]
constexpr double kAvogadro = 6.02214179e23;   // [1/mol]
constexpr double kGasConstant = 8.314472;     // [J/(mol K)]
constexpr double kAirMolarMass = 2.89644e-2;  // [kg/mol]
using constants::pi;

struct PartmcParticle {
  double r, D, c2, delta;  // radius, diffusivity, squared thermal speed, delta of the header formula
};

PartmcParticle partmc_particle(const PartmcGas& g, double d, double rho) {
  PartmcParticle s;
  s.r = 0.5 * d;
  const double kn = g.mean_free_path / s.r;
  const double cc = 1.0 + kn * (1.249 + 0.42 * std::exp(-0.87 / kn));
  const double kT = kBoltzmann * g.temperature;
  s.D = kT * cc / (6.0 * pi * g.viscosity * s.r);
  const double mass = rho * 4.0 / 3.0 * pi * s.r * s.r * s.r;
  s.c2 = 8.0 * kT / (pi * mass);
  const double l = 8.0 * s.D / (pi * std::sqrt(s.c2));
  s.delta = (std::pow(2.0 * s.r + l, 3) - std::pow(4.0 * s.r * s.r + l * l, 1.5)) / (6.0 * s.r * l) - 2.0 * s.r;
  return s;
}

// beta of the header's pair formula from the two particles' factors.
double partmc_pair(const PartmcParticle& a, const PartmcParticle& b) {
  const double rs = a.r + b.r, Ds = a.D + b.D;
  const double ds = std::sqrt(a.delta * a.delta + b.delta * b.delta), cs = std::sqrt(a.c2 + b.c2);
  return 4.0 * pi * rs * Ds / (rs / (rs + ds) + 4.0 * Ds / (rs * cs));
}

// The factors of every sample index a thread has evaluated, with the (d, rho) and the gas they were
// computed from: an entry is used only while all of them are bit for bit the same, so a merge or a
// split (new d or rho) recomputes it and the kernel is that of partmc_particle exactly.
struct PartmcFactorCache {
  struct Entry {
    double d = std::numeric_limits<double>::quiet_NaN(), rho = 0.0;  // NaN: empty (never equal)
    PartmcParticle f{};
  };
  double temperature = 0.0, viscosity = 0.0, mean_free_path = 0.0;
  std::vector<Entry> entries;
};

// (c.entries must hold index i.)
const PartmcParticle& cached_partmc_particle(PartmcFactorCache& c, std::size_t i, double d, double rho,
                                             const PartmcGas& g) {
  PartmcFactorCache::Entry& e = c.entries[i];
  if (!(e.d == d && e.rho == rho)) {
    e.d = d;
    e.rho = rho;
    e.f = partmc_particle(g, d, rho);
  }
  return e.f;
}
}  // namespace

PartmcGas PartmcGas::air(double temperature, double pressure) {
  PartmcGas g;
  g.temperature = temperature;
  const double rho_air = pressure * kAirMolarMass / (kGasConstant * temperature);
  g.viscosity = 1.8325e-5 * (416.16 / (temperature + 120.0)) * std::pow(temperature / 296.16, 1.5);
  const double c_air = std::sqrt(8.0 * kBoltzmann * temperature * kAvogadro / (pi * kAirMolarMass));
  g.mean_free_path = 2.0 * (g.viscosity / rho_air) / c_air;
  return g;
}

double beta_brownian_partmc(const PartmcGas& gas, double di, double dj, double rhoi, double rhoj) {
  return partmc_pair(partmc_particle(gas, di, rhoi), partmc_particle(gas, dj, rhoj));
}

double beta_brownian_partmc_cached(const PartmcGas& gas, const SampleSet& p, std::size_t i, std::size_t j) {
  thread_local PartmcFactorCache cache;
  if (cache.temperature != gas.temperature || cache.viscosity != gas.viscosity ||
      cache.mean_free_path != gas.mean_free_path) {  // another kernel's gas on this thread: start afresh
    cache.entries.assign(cache.entries.size(), PartmcFactorCache::Entry{});
    cache.temperature = gas.temperature;
    cache.viscosity = gas.viscosity;
    cache.mean_free_path = gas.mean_free_path;
  }
  const std::size_t top = std::max(i, j);
  if (top >= cache.entries.size()) cache.entries.resize(std::max(top + 1, 2 * cache.entries.size()));
  return partmc_pair(cached_partmc_particle(cache, i, p.d[i], p.rho[i], gas),
                     cached_partmc_particle(cache, j, p.d[j], p.rho[j], gas));
}

double partmc_thermal_speed_ratio() { return std::sqrt(kBoltzmann / constants::k_B); }

void partmc_prepare(const PartmcGas& g, CellBounds& cb) {
  if (!(cb.d_min > 0.0 && cb.mass_max > 0.0)) return;
  const double r = 0.5 * cb.d_min, kn = g.mean_free_path / r;
  const double kT = kBoltzmann * g.temperature;
  cb.diff_max = kT * (1.0 + kn * (1.249 + 0.42 * std::exp(-0.87 / kn))) / (6.0 * pi * g.viscosity * r);
  cb.gap_max = 8.0 * cb.diff_max / (pi * std::sqrt(8.0 * kT / (pi * cb.mass_max)));
}

}  // namespace agglo::acoustics
