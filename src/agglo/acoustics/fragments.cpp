#include "agglo/acoustics/fragments.hpp"

#include <algorithm>
#include <cmath>

#include "agglo/acoustics/merge.hpp"

namespace agglo::acoustics {

namespace {

// R(x): x rounded down or up to an integer, up with probability x - floor(x); x itself (no draw) when the
// broken weight W is not a whole number (the samplers never make one; it keeps the count positive).
double stochastic_round(double x, double W, CounterRng& rng) {
  if (W != std::floor(W)) return x;
  const double lo = std::floor(x);
  return lo + (rng.uniform() < x - lo ? 1.0 : 0.0);
}

// Sample k becomes `count` fragments of mass `mass` of the broken pair m (volumes in proportion to mass).
void set_fragments(SampleSet& p, std::size_t k, const Merged& m, double count, double mass) {
  const double share = mass / m.mass;
  p.vol_s[k] = share * m.vol_s;
  p.vol_l[k] = share * m.vol_l;
  p.mass[k] = mass;
  p.vx[k] = m.v.x;
  p.vy[k] = m.v.y;
  p.vz[k] = m.v.z;
  p.pop[k] = m.pop;
  p.w[k] = count;
  if (p.structured()) {  // primaries in proportion to mass (structure.hpp)
    p.np[k] = share * m.primaries.count;
    p.rp[k] = m.primaries.radius;
  }
  if (p.carries_charge) p.q[k] = share * m.charge;  // charge in proportion to mass
}

// The bin of a fragment class drawn in proportion to its mass share mu_b, by the uniform u.
std::size_t draw_fragment_bin(const FragmentStats& f, double u) {
  double total = 0.0;
  for (std::size_t b = 0; b < f.bins; ++b) total += f.bin_mass[b];
  double acc = 0.0;
  std::size_t last = 0;
  for (std::size_t b = 0; b < f.bins; ++b) {
    if (!(f.bin_mass[b] > 0.0)) continue;
    last = b;
    acc += f.bin_mass[b];
    if (u * total < acc) return b;
  }
  return last;  // u * total at the sum's rounding
}

// Sample k becomes the fragments of bin b holding the broken pairs' mass `held` = weight x mass [kg]:
// count c = R(held h_b / (mu_b M)) (at least 1), each of mass held / c (fragments.hpp).
void set_bin_fragments(SampleSet& p, std::size_t k, const Merged& m, const FragmentStats& f, std::size_t b,
                       double held, double W, CounterRng& rng) {
  const double c = std::max(1.0, stochastic_round(held * f.bin_number[b] / (f.bin_mass[b] * m.mass), W, rng));
  set_fragments(p, k, m, c, held / c);
}

// After an equal-weight break both samples keep their weight: i takes the pair's split-merge debt (and
// j's reference when i has none), and both are refreshed.
void pool_debt_and_refresh(SampleSet& p, std::size_t i, std::size_t j, const Gas& gas, const Sound& sound) {
  if (p.debt[i] <= 0.0) p.debt_ref[i] = p.debt_ref[j];
  p.debt[i] += p.debt[j];
  p.debt[j] = 0.0;
  p.refresh(i, gas, sound);
  p.refresh(j, gas, sound);
}

// Breakage by a fragment mass distribution (fragments.hpp): equal weights, i and j each hold half the mass
// in a bin drawn by u and by u + 1/2 (mod 1); unequal, l holds all of it in one bin.
void break_by_distribution(SampleSet& p, std::size_t i, std::size_t j, const FragmentStats& f, CounterRng& rng,
                           const Gas& gas, const Sound& sound) {
  const Merged m = merged_state(p, i, j);
  const double wi = p.w[i], wj = p.w[j];
  const double u = rng.uniform();
  if (wi == wj) {
    const double W = wi, held = 0.5 * W * m.mass, u2 = u < 0.5 ? u + 0.5 : u - 0.5;
    set_bin_fragments(p, i, m, f, draw_fragment_bin(f, u), held, W, rng);
    set_bin_fragments(p, j, m, f, draw_fragment_bin(f, u2), held, W, rng);
    pool_debt_and_refresh(p, i, j, gas, sound);
    return;
  }
  const std::size_t h = wi > wj ? i : j, l = wi > wj ? j : i;
  const double W = p.w[l];
  p.w[h] -= W;
  set_bin_fragments(p, l, m, f, draw_fragment_bin(f, u), W * m.mass, W, rng);
  p.refresh(l, gas, sound);
}

}  // namespace

void break_weighted(SampleSet& p, std::size_t i, std::size_t j, const FragmentStats& f, CounterRng& rng,
                    const Gas& gas, const Sound& sound) {
  if (f.bins > 0) return break_by_distribution(p, i, j, f, rng, gas, sound);
  const Merged m = merged_state(p, i, j);
  const double wi = p.w[i], wj = p.w[j];
  if (wi == wj) {
    const double W = wi, c = stochastic_round(W * (f.number - 1.0), W, rng);
    set_fragments(p, i, m, W, f.largest * m.mass);
    set_fragments(p, j, m, c, W * (1.0 - f.largest) * m.mass / c);
    pool_debt_and_refresh(p, i, j, gas, sound);
    return;
  }
  const std::size_t h = wi > wj ? i : j, l = wi > wj ? j : i;
  const double W = p.w[l];
  p.w[h] -= W;
  const bool largest = rng.uniform() < f.largest;
  const double c = stochastic_round(largest ? W / f.largest : W * (f.number - 1.0) / (1.0 - f.largest), W, rng);
  set_fragments(p, l, m, c, W * m.mass / c);
  p.refresh(l, gas, sound);
}

}  // namespace agglo::acoustics
