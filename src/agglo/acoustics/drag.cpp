#include "agglo/acoustics/drag.hpp"

#include <algorithm>
#include <cmath>

namespace agglo::acoustics {

namespace {
// First-order correction, in k xi, to the frozen-phase step (the acoustic or Stokes drift).
// Over a step the true forcing is A sin(psi(s) - k xi(s)) ~ A sin psi(s) - A k xi(s) cos psi(s),
// psi(s) = psi0 + w s, xi(s) = x(s) - x(0) from the zeroth-order (frozen-phase) solution:
//   xi = X(s) - X(0) + dv te (1 - E(s)),  X = -(A/(w D)) (cos psi + q sin psi),  E = exp(-s/te).
// The extra forcing f1 = -A k xi cos psi splits into
//   G (1 + cos 2psi + q sin 2psi) + H cos psi + K E(s) cos psi,
//   G = A^2 k/(2 w D), H = A k (X(0) - dv te), K = A k dv te,
// and te v1' + v1 = f1, v1(0) = 0 is solved in closed form for each part. Adds the correction to
// the end-of-step velocity (dvx) and displacement (dx). q = w te, D = 1 + q^2.
inline void drift_correction(double A, double k, double w, double iw, double te, double iD, double h, double E,
                             double omE, double s0, double c0, double s1, double c1, double dv, double& dx,
                             double& dvx) {
  // iw = 1/w, iD = 1/D
  const double q = w * te;
  const double G = 0.5 * A * A * k * iw * iD;
  const double X0 = -(A * iw * iD) * (c0 + q * s0);
  const double teomE = te * omE;
  // constant part G
  double v1 = G * omE;
  double x1 = G * (h - teomE);
  // G (cos 2psi + q sin 2psi): periodic response alpha cos 2psi + beta sin 2psi
  const double GD2 = G / (1.0 + 4.0 * q * q);
  const double al = GD2 * (1.0 - 2.0 * q * q), be = 3.0 * q * GD2;
  const double C20 = c0 * c0 - s0 * s0, S20 = 2.0 * s0 * c0, C21 = c1 * c1 - s1 * s1, S21 = 2.0 * s1 * c1;
  const double P20 = al * C20 + be * S20;
  v1 += (al * C21 + be * S21) - P20 * E;
  x1 += (al * (S21 - S20) - be * (C21 - C20)) * (0.5 * iw) - P20 * teomE;
  // H cos psi
  const double HD = A * k * (X0 - dv * te) * iD;  // H / D
  const double ab = HD, bb = HD * q;
  const double P10 = ab * c0 + bb * s0;
  v1 += (ab * c1 + bb * s1) - P10 * E;
  x1 += (ab * (s1 - s0) - bb * (c1 - c0)) * iw - P10 * teomE;
  // K E(s) cos psi: v1 = (K/q) E(s) (sin psi(s) - sin psi0), K/q = A k dv / w
  const double Kq = A * k * dv * iw;
  v1 += Kq * E * (s1 - s0);
  x1 += Kq * te * ((s0 - E * s1 - q * (E * c1 - c0)) * iD - s0 * omE);
  dx += x1;
  dvx += v1;
}
// Closed-form step of y (no forcing) and z (settling to the terminal velocity vt) over h, shared by
// the block and the one-sample exact steps. E = exp(-h/te), omE = 1 - E.
inline void transverse_step(SampleSet& p, std::size_t i, double te, double h, double E, double omE, double vt) {
  p.y[i] += p.vy[i] * te * omE;
  p.vy[i] *= E;
  const double dz = p.vz[i] - vt;
  p.z[i] += vt * h + dz * te * omE;
  p.vz[i] = vt + dz * E;
}

// Stages of the exact step of one sample, shared by the block step and the one-sample reference.
// s0, c0 = sin, cos(omega t - k x) of sample i. sin, cos(k x) come from the per-sample cache at x_ref
// rotated by delta = k (x - x_ref); the cache is refilled from libm when |delta| > 0.05 (x moved
// > 1.4 mm at 2 kHz, a wrap, or an empty cache).
inline void wave_phase(SampleSet& p, std::size_t i, double k, const Motion::StepTrig& tr, double& s0, double& c0) {
  double dlt = k * (p.x[i] - p.x_ref[i]);
  if (!(std::abs(dlt) <= 0.05)) {
    p.x_ref[i] = p.x[i];
    p.skx[i] = std::sin(k * p.x[i]);
    p.ckx[i] = std::cos(k * p.x[i]);
    dlt = 0.0;
  }
  // Taylor series of sin, cos(delta), |delta| <= 0.05: truncation below 1e-19.
  const double d2 = dlt * dlt;
  const double sd = dlt * (1.0 - d2 * (1.0 / 6) * (1.0 - d2 * (1.0 / 20) * (1.0 - d2 * (1.0 / 42))));
  const double cd = 1.0 - d2 * 0.5 * (1.0 - d2 * (1.0 / 12) * (1.0 - d2 * (1.0 / 30) * (1.0 - d2 * (1.0 / 56))));
  const double skx = p.skx[i] * cd + p.ckx[i] * sd, ckx = p.ckx[i] * cd - p.skx[i] * sd;
  s0 = tr.swt * ckx - tr.cwt * skx;  // sin(omega t - k x)
  c0 = tr.cwt * ckx + tr.swt * skx;
}

// Particle Reynolds number at the start of the step (gas velocity A s0).
inline double start_reynolds(const SampleSet& p, std::size_t i, const Gas& gas, double A, double s0) {
  const double sx = A * s0 - p.vx[i];
  const double slip = std::sqrt(sx * sx + p.vy[i] * p.vy[i] + p.vz[i] * p.vz[i]);
  return gas.reynolds(slip, p.mobility_diameters()[i]);
}

// tau_e = tau / C_I with C_I at the mid-step slip predicted with the start-of-step tau_e `te` (sound on).
inline double midstep_tau(const SampleSet& p, std::size_t i, const Gas& gas, const Sound& sound, double s0, double c0,
                          double te, double h, const Motion::StepTrig& tr) {
  const double A = sound.u_amp;
  const double Eh = std::exp(-(0.5 * h / te));
  const double q = sound.omega * te, D = 1.0 + q * q;
  const double sh = s0 * tr.cwh2 + c0 * tr.swh2, ch = c0 * tr.cwh2 - s0 * tr.swh2;
  const double vxh = A * (sh - q * ch) / D + (p.vx[i] - A * (s0 - q * c0) / D) * Eh;
  const double sxh = A * sh - vxh;
  const double vt = p.acc_z[i] * te;
  const double vyh = p.vy[i] * Eh, vzh = vt + (p.vz[i] - vt) * Eh;
  const double slh = std::sqrt(sxh * sxh + vyh * vyh + vzh * vzh);
  return p.tau[i] / Gas::inertia_correction_fast(gas.reynolds(slh, p.mobility_diameters()[i]));
}

// E = exp(-x), omE = 1 - exp(-x); expm1 only where 1 - exp(-x) would lose digits.
inline void decay(double x, double& E, double& omE) {
  if (x > 40.0) {  // exp(-x) < 4.3e-18: below the rounding of every term it multiplies
    E = 0.0;
    omE = 1.0;
  } else if (x > 0.01) {
    E = detail_exp_small(-x);  // inline polynomial exp (relative error ~1e-15)
    omE = 1.0 - E;
  } else {
    omE = -std::expm1(-x);
    E = 1.0 - omE;
  }
}

// Closed-form update of velocity and position of sample i over h with tau_e = te, E = exp(-h/te).
inline void exact_update(const Motion& m, SampleSet& p, std::size_t i, double te, double E, double omE, double s0,
                         double c0, const Motion::StepTrig& tr, double h) {
  const double A = m.sound.u_amp;
  if (A > 0.0) {
    const double w = m.sound.omega;
    const double q = w * te, iD = 1.0 / (1.0 + q * q), AD = A * iD;
    const double s1 = s0 * tr.cwh + c0 * tr.swh, c1 = c0 * tr.cwh - s0 * tr.swh;
    const double vs0 = AD * (s0 - q * c0), vs1 = AD * (s1 - q * c1);
    const double dX = -AD * ((c1 - c0) + q * (s1 - s0)) * tr.inv_omega;
    const double dv = p.vx[i] - vs0;
    double dx = dX + dv * te * omE, vx = vs1 + dv * E;
    drift_correction(A, m.sound.wavenumber, w, tr.inv_omega, te, iD, h, E, omE, s0, c0, s1, c1, dv, dx, vx);
    p.x[i] += dx;
    p.vx[i] = vx;
  } else {
    p.x[i] += p.vx[i] * te * omE;
    p.vx[i] *= E;
  }
  transverse_step(p, i, te, h, E, omE, p.acc_z[i] * te);
  m.wrap(p, i);
}
}  // namespace

double Motion::effective_tau(const SampleSet& p, std::size_t i, double t) const {
  if (!inertia_correction) return p.tau[i];
  const double ug = sound.u_amp * std::sin(sound.omega * t - sound.wavenumber * p.x[i]);
  const double sx = ug - p.vx[i];
  const double slip = std::sqrt(sx * sx + p.vy[i] * p.vy[i] + p.vz[i] * p.vz[i]);
  return p.tau[i] / Gas::inertia_correction(gas.reynolds(slip, p.mobility_diameters()[i]));
}

void Motion::set_steady_velocity(SampleSet& p, std::size_t i, double t) const {
  // Iterate tau_e <-> velocity twice so that C_I matches the steady slip.
  double te = p.tau[i];
  const double a = gas.gravity * (p.rho[i] - gas.density) / p.rho[i];
  for (int it = 0; it < 3; ++it) {
    const double q = sound.omega * te;
    const double psi = sound.omega * t - sound.wavenumber * p.x[i];
    p.vx[i] = sound.u_amp * (std::sin(psi) - q * std::cos(psi)) / (1.0 + q * q);
    p.vy[i] = 0.0;
    p.vz[i] = -a * te;
    te = effective_tau(p, i, t);
  }
}

void Motion::wrap(SampleSet& p, std::size_t i) const {
  double* c[3] = {&p.x[i], &p.y[i], &p.z[i]};
  for (int k = 0; k < 3; ++k) {
    double& v = *c[k];
    if (v < 0.0 || v >= domain.L[k]) {
      v -= domain.L[k] * std::floor(v / domain.L[k]);
      if (v >= domain.L[k]) v = 0.0;  // rounding of -tiny + L
    }
  }
}

Motion::StepTrig Motion::trig(double t, double h) const {
  return {std::sin(sound.omega * t),       std::cos(sound.omega * t),       std::sin(sound.omega * h),
          std::cos(sound.omega * h),       std::sin(0.5 * sound.omega * h), std::cos(0.5 * sound.omega * h),
          1.0 / sound.omega};
}

// The exact step of one sample, written plainly: the reference the block step is tested against
// (tests/acoustics/test_motion.cpp, bit for bit).
void Motion::advance_exact(SampleSet& p, std::size_t i, const StepTrig& tr, double h) const {
  const double A = sound.u_amp;
  double s0 = 0.0, c0 = 1.0;
  if (A > 0.0) wave_phase(p, i, sound.wavenumber, tr, s0, c0);
  double te = p.tau[i];
  if (inertia_correction) {
    const double ci = Gas::inertia_correction_fast(start_reynolds(p, i, gas, A, s0));
    te = p.tau[i] / ci;
    if (A > 0.0 && ci > 1.001) te = midstep_tau(p, i, gas, sound, s0, c0, te, h, tr);
  }
  double E, omE;
  decay(h / te, E, omE);
  exact_update(*this, p, i, te, E, omE, s0, c0, tr, h);
}

// The step of one sample is a long chain of dependent operations (phase -> slip -> C_I -> tau_e ->
// exp -> update). To let the processor overlap many samples, the step runs the stages of
// advance_exact over blocks of samples; every sample sees exactly the arithmetic of advance_exact.
void Motion::advance_exact_block(SampleSet& p, std::size_t begin, std::size_t end, const StepTrig& tr,
                                 double h) const {
  constexpr std::size_t B = 64;
  double S0[B], C0[B], TE[B], CI[B], EE[B], OME[B];
  const double A = sound.u_amp;
  for (std::size_t i0 = begin; i0 < end; i0 += B) {
    const std::size_t m = std::min(B, end - i0);
    for (std::size_t a = 0; a < m; ++a) {
      S0[a] = 0.0;
      C0[a] = 1.0;
    }
    if (A > 0.0)
      for (std::size_t a = 0; a < m; ++a) wave_phase(p, i0 + a, sound.wavenumber, tr, S0[a], C0[a]);
    for (std::size_t a = 0; a < m; ++a) TE[a] = p.tau[i0 + a];
    if (inertia_correction) {
      for (std::size_t a = 0; a < m; ++a) CI[a] = start_reynolds(p, i0 + a, gas, A, S0[a]);
      for (std::size_t a = 0; a < m; ++a) CI[a] = Gas::inertia_correction_fast(CI[a]);
      for (std::size_t a = 0; a < m; ++a) TE[a] = p.tau[i0 + a] / CI[a];
      if (A > 0.0)
        for (std::size_t a = 0; a < m; ++a)
          if (CI[a] > 1.001) TE[a] = midstep_tau(p, i0 + a, gas, sound, S0[a], C0[a], TE[a], h, tr);
    }
    for (std::size_t a = 0; a < m; ++a) decay(h / TE[a], EE[a], OME[a]);
    for (std::size_t a = 0; a < m; ++a) exact_update(*this, p, i0 + a, TE[a], EE[a], OME[a], S0[a], C0[a], tr, h);
  }
}

void Motion::advance_explicit(SampleSet& p, std::size_t i, double t, double h) const {
  const double te = effective_tau(p, i, t);
  const double ug = sound.u_amp * std::sin(sound.omega * t - sound.wavenumber * p.x[i]);
  const double a = gas.gravity * (p.rho[i] - gas.density) / p.rho[i];
  p.vx[i] += h * (ug - p.vx[i]) / te;
  p.vy[i] += h * (-p.vy[i]) / te;
  p.vz[i] += h * (-p.vz[i] / te - a);
  p.x[i] += h * p.vx[i];
  p.y[i] += h * p.vy[i];
  p.z[i] += h * p.vz[i];
  wrap(p, i);
}

void Motion::advance(SampleSet& p, std::size_t begin, std::size_t end, double t, double h, int substeps) const {
  if (integrator == Integrator::none) return;
  if (integrator == Integrator::exact) {
    const double hs = h / substeps;
    for (int s = 0; s < substeps; ++s) {
      const StepTrig tr = trig(t + s * hs, hs);
      advance_exact_pairs(p, begin, end, tr, hs);
    }
    return;
  }
  const double hs = h / substeps;
  for (std::size_t i = begin; i < end; ++i)
    for (int s = 0; s < substeps; ++s) advance_explicit(p, i, t + s * hs, hs);
}

}  // namespace agglo::acoustics
