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

void SampleSet::resize(std::size_t n) {
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &vol_s, &vol_l, &mass, &w, &debt, &debt_ref, &d, &rho, &cc, &tau,
                  &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd, &acc_z})
    v->resize(n, 0.0);
  x_ref.resize(n, std::numeric_limits<double>::quiet_NaN());
  skx.resize(n, 0.0);
  ckx.resize(n, 1.0);
  pop.resize(n, 0);
  id.resize(n, 0);
}

void SampleSet::reserve(std::size_t n) {
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &vol_s, &vol_l, &mass, &w, &debt, &debt_ref, &d, &rho, &cc, &tau,
                  &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd, &acc_z, &x_ref, &skx, &ckx})
    v->reserve(n);
  pop.reserve(n);
  id.reserve(n);
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
  refresh(i, gas, sound);
  return i;
}

void SampleSet::refresh(std::size_t i, const Gas& gas, const Sound& sound) {
  const double v = vol_s[i] + vol_l[i];
  d[i] = std::cbrt(6.0 * v / constants::pi);
  rho[i] = mass[i] / v;
  cc[i] = gas.slip_correction(d[i]);
  tau[i] = rho[i] * d[i] * d[i] * cc[i] / (18.0 * gas.viscosity);
  const double wt = sound.omega * tau[i];
  const double s = std::sqrt(1.0 + wt * wt);
  slip_l[i] = wt / s;
  cphi[i] = 1.0 / s;
  sphi[i] = wt / s;
  phase_code[i] = vol_l[i] <= 0.0 ? 0.0 : (vol_s[i] <= 0.0 ? 1.0 : 2.0);
  dl[i] = d[i] * slip_l[i];
  ccd[i] = cc[i] / d[i];
  acc_z[i] = -gas.gravity * (rho[i] - gas.density) / rho[i];
}

void SampleSet::copy_derived(std::size_t from, std::size_t to) {
  for (auto* v : {&d, &rho, &cc, &tau, &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd, &acc_z}) (*v)[to] = (*v)[from];
}

void SampleSet::copy_sample(std::size_t from, std::size_t to) {
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &vol_s, &vol_l, &mass, &w, &debt, &debt_ref, &d, &rho, &cc, &tau,
                  &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd, &acc_z, &x_ref, &skx, &ckx})
    (*v)[to] = (*v)[from];
  pop[to] = pop[from];
}

}  // namespace agglo::acoustics

namespace agglo::acoustics {

void SampleSet::permute(const std::vector<std::uint32_t>& order) {
  auto apply = [&](auto& v) {
    auto old = v;
    for (std::size_t k = 0; k < order.size(); ++k) v[k] = old[order[k]];
  };
  for (auto* v : {&x, &y, &z, &vx, &vy, &vz, &vol_s, &vol_l, &mass, &w, &debt, &debt_ref, &d, &rho, &cc, &tau,
                  &slip_l, &cphi, &sphi, &phase_code, &dl, &ccd, &acc_z, &x_ref, &skx, &ckx})
    apply(*v);
  apply(pop);
  apply(id);
}

}  // namespace agglo::acoustics
