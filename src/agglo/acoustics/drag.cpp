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
}  // namespace

double Motion::effective_tau(const SampleSet& p, std::size_t i, double t) const {
  if (!inertia_correction) return p.tau[i];
  const double ug = sound.u_amp * std::sin(sound.omega * t - sound.wavenumber * p.x[i]);
  const double sx = ug - p.vx[i];
  const double slip = std::sqrt(sx * sx + p.vy[i] * p.vy[i] + p.vz[i] * p.vz[i]);
  return p.tau[i] / Gas::inertia_correction(gas.reynolds(slip, p.d[i]));
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

void Motion::advance_exact(SampleSet& p, std::size_t i, const StepTrig& tr, double h) const {
  advance_exact_block(p, i, i + 1, tr, h);
}

// The step of one sample is a long chain of dependent operations (phase -> slip -> C_I -> tau_e ->
// exp -> update). To let the processor overlap many samples, the step runs in stages over blocks
// of samples; every sample sees exactly the arithmetic of the one-sample form.
void Motion::advance_exact_block(SampleSet& p, std::size_t begin, std::size_t end, const StepTrig& tr,
                                 double h) const {
  constexpr std::size_t B = 64;
  double S0[B], C0[B], TE[B], CI[B], EE[B], OME[B];
  const double A = sound.u_amp;
  const double k = sound.wavenumber;
  for (std::size_t i0 = begin; i0 < end; i0 += B) {
    const std::size_t m = std::min(B, end - i0);
    // Stage 1: sin, cos(omega t - k x).
    if (A > 0.0) {
      for (std::size_t a = 0; a < m; ++a) {
        const std::size_t i = i0 + a;
        // sin, cos(k x) from the per-sample cache at x_ref rotated by delta = k (x - x_ref); the cache is
        // refilled from libm when |delta| > 0.05 (x moved > 1.4 mm at 2 kHz, a wrap, or an empty cache).
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
        const double cd =
            1.0 - d2 * 0.5 * (1.0 - d2 * (1.0 / 12) * (1.0 - d2 * (1.0 / 30) * (1.0 - d2 * (1.0 / 56))));
        const double skx = p.skx[i] * cd + p.ckx[i] * sd, ckx = p.ckx[i] * cd - p.skx[i] * sd;
        S0[a] = tr.swt * ckx - tr.cwt * skx;  // sin(omega t - k x)
        C0[a] = tr.cwt * ckx + tr.swt * skx;
      }
    } else {
      for (std::size_t a = 0; a < m; ++a) {
        S0[a] = 0.0;
        C0[a] = 1.0;
      }
    }
    // Stage 2: tau_e = tau / C_I (C_I at the start of the step; at mid-step for C_I - 1 > 1e-3).
    if (inertia_correction) {
      for (std::size_t a = 0; a < m; ++a) {
        const std::size_t i = i0 + a;
        const double sx = A * S0[a] - p.vx[i];
        const double slip = std::sqrt(sx * sx + p.vy[i] * p.vy[i] + p.vz[i] * p.vz[i]);
        CI[a] = gas.reynolds(slip, p.d[i]);
      }
      for (std::size_t a = 0; a < m; ++a) CI[a] = Gas::inertia_correction_fast(CI[a]);
      for (std::size_t a = 0; a < m; ++a) TE[a] = p.tau[i0 + a] / CI[a];
      for (std::size_t a = 0; a < m; ++a) {
        if (!(CI[a] > 1.001)) continue;
        const std::size_t i = i0 + a;
        const double s0 = S0[a], c0 = C0[a];
        double te = TE[a];
        // Predict the slip at mid-step with this C_I, then take C_I there.
        const double xh = 0.5 * h / te, Eh = std::exp(-xh);
        double vxh = p.vx[i] * Eh;
        if (A > 0.0) {
          const double q = sound.omega * te, D = 1.0 + q * q;
          const double sh = s0 * tr.cwh2 + c0 * tr.swh2, ch = c0 * tr.cwh2 - s0 * tr.swh2;
          vxh = A * (sh - q * ch) / D + (p.vx[i] - A * (s0 - q * c0) / D) * Eh;
          const double sxh = A * sh - vxh;
          const double vt = p.acc_z[i] * te;
          const double vyh = p.vy[i] * Eh, vzh = vt + (p.vz[i] - vt) * Eh;
          const double slh = std::sqrt(sxh * sxh + vyh * vyh + vzh * vzh);
          te = p.tau[i] / Gas::inertia_correction_fast(gas.reynolds(slh, p.d[i]));
        }
        TE[a] = te;
      }
    } else {
      for (std::size_t a = 0; a < m; ++a) TE[a] = p.tau[i0 + a];
    }
    // Stage 3: exp(-h/tau_e) and 1 - exp(-h/tau_e); expm1 only where 1 - exp(-x) would lose digits.
    for (std::size_t a = 0; a < m; ++a) {
      const double x = h / TE[a];
      if (x > 40.0) {  // exp(-x) < 4.3e-18: below the rounding of every term it multiplies
        EE[a] = 0.0;
        OME[a] = 1.0;
      } else if (x > 0.01) {
        EE[a] = detail_exp_small(-x);  // inline polynomial exp (relative error ~1e-15)
        OME[a] = 1.0 - EE[a];
      } else {
        OME[a] = -std::expm1(-x);
        EE[a] = 1.0 - OME[a];
      }
    }
    // Stage 4: closed-form update of velocity and position.
    for (std::size_t a = 0; a < m; ++a) {
      const std::size_t i = i0 + a;
      const double te = TE[a], E = EE[a], omE = OME[a], s0 = S0[a], c0 = C0[a];
      if (A > 0.0) {
        const double w = sound.omega;
        const double q = w * te, iD = 1.0 / (1.0 + q * q), AD = A * iD;
        const double s1 = s0 * tr.cwh + c0 * tr.swh, c1 = c0 * tr.cwh - s0 * tr.swh;
        const double vs0 = AD * (s0 - q * c0), vs1 = AD * (s1 - q * c1);
        const double dX = -AD * ((c1 - c0) + q * (s1 - s0)) * tr.inv_omega;
        const double dv = p.vx[i] - vs0;
        double dx = dX + dv * te * omE, vx = vs1 + dv * E;
        drift_correction(A, k, w, tr.inv_omega, te, iD, h, E, omE, s0, c0, s1, c1, dv, dx, vx);
        p.x[i] += dx;
        p.vx[i] = vx;
      } else {
        p.x[i] += p.vx[i] * te * omE;
        p.vx[i] *= E;
      }
      transverse_step(p, i, te, h, E, omE, p.acc_z[i] * te);
      wrap(p, i);
    }
  }
}

void Motion::advance_exact(SampleSet& p, std::size_t i, double t, double h) const {
  const double te = effective_tau(p, i, t);
  const double E = std::exp(-h / te);
  const double omE = -std::expm1(-h / te);
  // x: forcing u_amp sin(psi), psi = omega t - k x0 (x frozen in the phase over the step).
  if (sound.u_amp > 0.0) {
    const double w = sound.omega, A = sound.u_amp;
    const double q = w * te, D = 1.0 + q * q;
    const double psi0 = w * t - sound.wavenumber * p.x[i];
    const double s0 = std::sin(psi0), c0 = std::cos(psi0);
    const double s1 = std::sin(psi0 + w * h), c1 = std::cos(psi0 + w * h);
    const double vs0 = A * (s0 - q * c0) / D, vs1 = A * (s1 - q * c1) / D;
    const double X0 = -A * (c0 + q * s0) / (w * D), X1 = -A * (c1 + q * s1) / (w * D);
    const double dv = p.vx[i] - vs0;
    double dx = (X1 - X0) + dv * te * omE, vx = vs1 + dv * E;
    drift_correction(A, sound.wavenumber, w, 1.0 / w, te, 1.0 / D, h, E, omE, s0, c0, s1, c1, dv, dx, vx);
    p.x[i] += dx;
    p.vx[i] = vx;
  } else {
    p.x[i] += p.vx[i] * te * omE;
    p.vx[i] *= E;
  }
  transverse_step(p, i, te, h, E, omE, -gas.gravity * (p.rho[i] - gas.density) / p.rho[i] * te);
  wrap(p, i);
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
      advance_exact_block(p, begin, end, tr, hs);
    }
    return;
  }
  const double hs = h / substeps;
  for (std::size_t i = begin; i < end; ++i)
    for (int s = 0; s < substeps; ++s) advance_explicit(p, i, t + s * hs, hs);
}

}  // namespace agglo::acoustics
