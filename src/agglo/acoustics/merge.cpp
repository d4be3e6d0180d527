#include "agglo/acoustics/merge.hpp"

#include "agglo/acoustics/outcomes.hpp"

#include <cmath>

namespace agglo::acoustics {

Merged merged_state(const SampleSet& p, std::size_t i, std::size_t j) {
  Merged m;
  m.vol_s = p.vol_s[i] + p.vol_s[j];
  m.vol_l = p.vol_l[i] + p.vol_l[j];
  m.mass = p.mass[i] + p.mass[j];
  const double mi = p.mass[i], mj = p.mass[j];
  m.v = Vec3{(mi * p.vx[i] + mj * p.vx[j]) / m.mass, (mi * p.vy[i] + mj * p.vy[j]) / m.mass,
             (mi * p.vz[i] + mj * p.vz[j]) / m.mass};
  m.pop = p.volume(i) >= p.volume(j) ? p.pop[i] : p.pop[j];
  if (p.structured()) m.primaries = merged_primaries(p.np[i], p.rp[i], p.np[j], p.rp[j]);
  if (p.carries_charge) m.charge = p.q[i] + p.q[j];
  return m;
}

namespace {
void assign(SampleSet& p, std::size_t k, const Merged& m) {
  p.vol_s[k] = m.vol_s;
  p.vol_l[k] = m.vol_l;
  p.mass[k] = m.mass;
  p.vx[k] = m.v.x;
  p.vy[k] = m.v.y;
  p.vz[k] = m.v.z;
  p.pop[k] = m.pop;
  if (p.structured()) {
    p.np[k] = m.primaries.count;
    p.rp[k] = m.primaries.radius;
  }
  if (p.carries_charge) p.q[k] = m.charge;
}
// w == floor(w) && fmod(w, 2) == 1 without fmod: w / 2 is exact, and not an integer exactly when a positive
// integer w is odd (at w >= 2^53 every double is even, and w / 2 an integer).
bool is_odd_integer(double w) { return w > 0.0 && w == std::floor(w) && std::floor(0.5 * w) != 0.5 * w; }
}  // namespace

void coalesce_weighted(SampleSet& p, std::size_t i, std::size_t j, const Gas& gas, const Sound& sound) {
  const Merged m = merged_state(p, i, j);
  const double wi = p.w[i], wj = p.w[j];
  if (wi == wj) {
    if (is_odd_integer(wi)) {  // eq. 19
      p.w[i] = 0.5 * (wi + 1.0);
      p.w[j] = 0.5 * (wj - 1.0);
    } else {  // eq. 18
      p.w[i] = 0.5 * wi;
      p.w[j] = 0.5 * wj;
    }
    assign(p, i, m);
    assign(p, j, m);
    // The debts of both samples now belong to merged particles of the same group mass.
    if (p.debt[i] <= 0.0) p.debt_ref[i] = p.debt_ref[j];
    p.debt[i] += p.debt[j];
    p.debt[j] = 0.0;
    p.refresh(i, gas, sound);
    p.copy_derived(i, j);
  } else if (wi > wj) {  // eq. 20
    p.w[i] = wi - wj;
    assign(p, j, m);
    p.refresh(j, gas, sound);
  } else {  // eq. 21
    p.w[j] = wj - wi;
    assign(p, i, m);
    p.refresh(i, gas, sound);
  }
}

double rebound_weighted(SampleSet& p, std::size_t i, std::size_t j, const Vec3& n, double e, double f) {
  const Vec3 vi{p.vx[i], p.vy[i], p.vz[i]}, vj{p.vx[j], p.vy[j], p.vz[j]};
  Vec3 vir, vjr;
  hard_sphere_rebound(vi, vj, p.mass[i], p.mass[j], n, e, f, vir, vjr);
  const double wi = p.w[i], wj = p.w[j];
  auto set = [&](std::size_t k, const Vec3& v) {
    p.vx[k] = v.x;
    p.vy[k] = v.y;
    p.vz[k] = v.z;
  };
  if (wi == wj) {  // eq. 26
    set(i, vir);
    set(j, vjr);
    return 0.0;
  }
  // Split the heavier sample h (old velocity v0, rebound velocity vr), light sample l.
  const bool i_heavy = wi > wj;
  const std::size_t h = i_heavy ? i : j, l = i_heavy ? j : i;
  const double wh = p.w[h], wl = p.w[l];
  const Vec3 v0 = i_heavy ? vi : vj, vr = i_heavy ? vir : vjr;
  const Vec3 vm = (wl * vr + (wh - wl) * v0) / wh;  // eq. 25
  const double dE = 0.5 * p.mass[h] * (wl * norm2(vr) + (wh - wl) * norm2(v0) - wh * norm2(vm));  // eq. 29
  set(h, vm);
  set(l, i_heavy ? vjr : vir);  // eqs. 27-28
  if (dE > 0.0) {
    p.debt_ref[h] = (p.debt[h] > 0.0) ? p.debt_ref[h] : wh * p.mass[h];
    p.debt[h] += dE;
  }
  return dE > 0.0 ? dE : 0.0;
}

bool add_relative_energy(SampleSet& p, std::size_t s, std::size_t t, double dE) {
  const double Ms = p.w[s] * p.mass[s], Mt = p.w[t] * p.mass[t];
  const Vec3 vs{p.vx[s], p.vy[s], p.vz[s]}, vt{p.vx[t], p.vy[t], p.vz[t]};
  const Vec3 g = vs - vt;
  const double g2 = norm2(g);
  if (!(g2 > 0.0)) return false;
  const double mu = Ms * Mt / (Ms + Mt);
  const double scale = std::sqrt(1.0 + dE / (0.5 * mu * g2));
  const Vec3 vcm = (Ms * vs + Mt * vt) / (Ms + Mt);
  const Vec3 gn = g * scale;
  const Vec3 ns = vcm + gn * (Mt / (Ms + Mt)), nt = vcm - gn * (Ms / (Ms + Mt));
  p.vx[s] = ns.x; p.vy[s] = ns.y; p.vz[s] = ns.z;
  p.vx[t] = nt.x; p.vy[t] = nt.y; p.vz[t] = nt.z;
  return true;
}

double kinetic_energy(const SampleSet& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    e += 0.5 * p.w[i] * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i] + p.vz[i] * p.vz[i]);
  return e;
}

Vec3 momentum(const SampleSet& p) {
  Vec3 m;
  for (std::size_t i = 0; i < p.size(); ++i) m += p.w[i] * p.mass[i] * Vec3{p.vx[i], p.vy[i], p.vz[i]};
  return m;
}

}  // namespace agglo::acoustics
