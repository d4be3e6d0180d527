#include "agglo/acoustics/samples.hpp"

#include <cmath>
#include <limits>

#include "agglo/core/constants.hpp"

namespace agglo::acoustics {

const char* phase_name(Phase p) {
  switch (p) {
    case Phase::solid: return "solid";
    case Phase::liquid: return "liquid";
    case Phase::mixed: return "mixed";
  }
  return "?";
}

namespace {
// The caches that follow from d, rho, C_c and tau of sample i; dmob is the diameter of C_c / d (mobility).
inline void finish_sample_caches(SampleSet& p, std::size_t i, double dmob, const Gas& gas, const Sound& sound) {
  const double wt = sound.omega * p.tau[i];
  const double s = std::sqrt(1.0 + wt * wt);
  p.slip_l[i] = wt / s;
  p.cphi[i] = 1.0 / s;
  p.sphi[i] = wt / s;
  p.phase_code[i] = p.vol_l[i] <= 0.0 ? 0.0 : (p.vol_s[i] <= 0.0 ? 1.0 : 2.0);
  p.dl[i] = p.d[i] * p.slip_l[i];
  p.ccd[i] = p.cc[i] / dmob;
  p.acc_z[i] = -gas.gravity * (p.rho[i] - gas.density) / p.rho[i];
}
}  // namespace

void SampleSet::resize(std::size_t n) {
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &vol_s, &vol_l, &mass, &w, &debt, &debt_ref, &d, &rho, &cc, &tau,
                  &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd, &acc_z})
    v->resize(n, 0.0);
  x_ref.resize(n, std::numeric_limits<double>::quiet_NaN());
  skx.resize(n, 0.0);
  ckx.resize(n, 1.0);
  pop.resize(n, 0);
  id.resize(n, 0);
  each_structure_array([&](std::vector<double>& v) { v.resize(n, 0.0); });
}

void SampleSet::reserve(std::size_t n) {
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &vol_s, &vol_l, &mass, &w, &debt, &debt_ref, &d, &rho, &cc, &tau,
                  &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd, &acc_z, &x_ref, &skx, &ckx})
    v->reserve(n);
  pop.reserve(n);
  id.reserve(n);
  each_structure_array([&](std::vector<double>& v) { v.reserve(n); });
}

std::size_t SampleSet::add(double x_, double y_, double z_, double vs, double vl, double m, double w_, int p,
                             const Gas& gas, const Sound& sound) {
  const std::size_t i = size();
  for (auto* v : {&vx, &vy, &vz, &debt, &debt_ref, &d, &rho, &cc, &tau, &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd,
                  &acc_z, &skx})
    v->push_back(0.0);
  ckx.push_back(1.0);
  x_ref.push_back(std::numeric_limits<double>::quiet_NaN());
  x.push_back(x_);
  y.push_back(y_);
  z.push_back(z_);
  vol_s.push_back(vs);
  vol_l.push_back(vl);
  mass.push_back(m);
  w.push_back(w_);
  pop.push_back(p);
  id.push_back(i);
  if (structured()) {  // one compact primary of its own size (set_primaries makes it an aggregate)
    np.push_back(vs > 0.0 ? 1.0 : 0.0);
    rp.push_back(vs > 0.0 ? 0.5 * std::cbrt(6.0 * vs / constants::pi) : 0.0);
    dm.push_back(0.0);
  }
  if (carries_charge) q.push_back(0.0);  // uncharged until its population sets it
  refresh(i, gas, sound);
  return i;
}

double SampleSet::volume_diameter(std::size_t i) const {
  return structured() ? std::cbrt(6.0 * (vol_s[i] + vol_l[i]) / constants::pi) : d[i];
}

void SampleSet::set_primaries(std::size_t i, double r, const Gas& gas, const Sound& sound) {
  rp[i] = r;
  np[i] = vol_s[i] / (4.0 / 3.0 * constants::pi * r * r * r);
  refresh(i, gas, sound);
}

// The structure.hpp radii: d = 2 R_c, d_m = 2 R_m; C_c, tau and C_c / d_m from d_m (compact: the lines of
// refresh below).
void SampleSet::refresh_structured(std::size_t i, const Gas& gas, const Sound& sound) {
  const double v = vol_s[i] + vol_l[i];
  const double dv = std::cbrt(6.0 * v / constants::pi);
  const StructureLaw& law = structure_laws[static_cast<std::size_t>(pop[i])];
  const bool aggregate = law.fractal && vol_l[i] <= 0.0;
  rho[i] = mass[i] / v;
  if (aggregate) {
    d[i] = 2.0 * collision_radius(law, np[i], rp[i], 0.5 * dv);
    dm[i] = 2.0 * mobility_radius(law, np[i], rp[i], 0.5 * dv);
    cc[i] = gas.slip_correction(dm[i]);
    tau[i] = mass[i] * cc[i] / (3.0 * constants::pi * gas.viscosity * dm[i]);
  } else {
    d[i] = dv;
    dm[i] = dv;
    cc[i] = gas.slip_correction(d[i]);
    tau[i] = rho[i] * d[i] * d[i] * cc[i] / (18.0 * gas.viscosity);
  }
  finish_sample_caches(*this, i, dm[i], gas, sound);
}

void SampleSet::refresh(std::size_t i, const Gas& gas, const Sound& sound) {
  if (structured()) {
    refresh_structured(i, gas, sound);
    return;
  }
  const double v = vol_s[i] + vol_l[i];
  d[i] = std::cbrt(6.0 * v / constants::pi);
  rho[i] = mass[i] / v;
  cc[i] = gas.slip_correction(d[i]);
  tau[i] = rho[i] * d[i] * d[i] * cc[i] / (18.0 * gas.viscosity);
  finish_sample_caches(*this, i, d[i], gas, sound);
}

void SampleSet::copy_derived(std::size_t from, std::size_t to) {
  for (auto* v : {&d, &rho, &cc, &tau, &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd, &acc_z}) (*v)[to] = (*v)[from];
  if (structured()) dm[to] = dm[from];
}

void SampleSet::copy_sample(std::size_t from, std::size_t to) {
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &vol_s, &vol_l, &mass, &w, &debt, &debt_ref, &d, &rho, &cc, &tau,
                  &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd, &acc_z, &x_ref, &skx, &ckx})
    (*v)[to] = (*v)[from];
  pop[to] = pop[from];
  each_structure_array([&](std::vector<double>& v) { v[to] = v[from]; });
}

}  // namespace agglo::acoustics

namespace agglo::acoustics {

void SampleSet::permute(const std::vector<std::uint32_t>& order, int part, int parts) {
  int j = 0;  // the array's number
  auto apply = [&](auto& v) {
    if (j++ % parts != part) return;
    auto old = v;
    for (std::size_t k = 0; k < order.size(); ++k) v[k] = old[order[k]];
  };
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &vol_s, &vol_l, &mass, &w, &debt, &debt_ref, &d, &rho, &cc, &tau,
                  &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd, &acc_z, &x_ref, &skx, &ckx})
    apply(*v);
  apply(pop);
  apply(id);
  each_structure_array(apply);
}

}  // namespace agglo::acoustics
