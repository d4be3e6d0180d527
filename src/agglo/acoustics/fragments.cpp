#include "agglo/acoustics/fragments.hpp"

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

}  // namespace

void break_weighted(SampleSet& p, std::size_t i, std::size_t j, const FragmentStats& f, CounterRng& rng,
                    const Gas& gas, const Sound& sound) {
  const Merged m = merged_state(p, i, j);
  const double wi = p.w[i], wj = p.w[j];
  if (wi == wj) {
    const double W = wi, c = stochastic_round(W * (f.number - 1.0), W, rng);
    set_fragments(p, i, m, W, f.largest * m.mass);
    set_fragments(p, j, m, c, W * (1.0 - f.largest) * m.mass / c);
    if (p.debt[i] <= 0.0) p.debt_ref[i] = p.debt_ref[j];
    p.debt[i] += p.debt[j];
    p.debt[j] = 0.0;
    p.refresh(i, gas, sound);
    p.refresh(j, gas, sound);
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
