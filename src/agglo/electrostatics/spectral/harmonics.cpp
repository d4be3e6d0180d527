#include "agglo/electrostatics/spectral/harmonics.hpp"

#include <cmath>
#include <complex>

namespace agglo::es::sh {

namespace {

using cplx = std::complex<double>;

// Pt_l^m(cos theta) for 0 <= m <= l <= L at index idx(l, m) (m >= 0 part only).
void legendre(int L, double ct, double st, double* p) {
  p[idx(0, 0)] = 1.0;
  for (int m = 0; m <= L; ++m) {
    if (m > 0) p[idx(m, m)] = std::sqrt((2.0 * m - 1.0) / (2.0 * m)) * st * p[idx(m - 1, m - 1)];
    if (m + 1 <= L) p[idx(m + 1, m)] = std::sqrt(2.0 * m + 1.0) * ct * p[idx(m, m)];
    for (int l = m + 2; l <= L; ++l) {
      p[idx(l, m)] = ((2.0 * l - 1.0) * ct * p[idx(l - 1, m)] -
                      std::sqrt(double((l - 1) * (l - 1) - m * m)) * p[idx(l - 2, m)]) /
                     std::sqrt(double(l * l - m * m));
    }
  }
}

void eval_scaled(int L, const Vec3& x, double* out, int mode) {
  double rho2 = x.x * x.x + x.y * x.y;
  double r = std::sqrt(rho2 + x.z * x.z);
  double rho = std::sqrt(rho2);
  double ct = r > 0 ? x.z / r : 1.0, st = r > 0 ? rho / r : 0.0;
  double cp = rho > 0 ? x.x / rho : 1.0, sp = rho > 0 ? x.y / rho : 0.0;
  legendre(L, ct, st, out);  // m >= 0 slots hold Pt_l^m
  // radial factor per degree
  double rl = (mode == 0) ? 1.0 : (mode == 1 ? 1.0 : 1.0 / r);
  double step = (mode == 0) ? 1.0 : (mode == 1 ? r : 1.0 / r);
  for (int l = 0; l <= L; ++l) {
    double c = 1.0, s = 0.0;  // cos(m phi), sin(m phi)
    for (int m = 0; m <= l; ++m) {
      double pv = out[idx(l, m)] * rl;
      out[idx(l, m)] = pv * c;
      if (m > 0) out[idx(l, -m)] = pv * s;
      double c2 = c * cp - s * sp;
      s = s * cp + c * sp;
      c = c2;
    }
    rl *= step;
  }
}

// Real coefficients a (per degree l) <-> complex v_mu with f = sum_mu v_mu Sc(l, mu), where
// Sc(l, m) = Pt_l^m e^{i m phi} for m >= 0 and Sc(l, -m) = conj(Sc(l, m)).
void to_complex(int L, const double* a, cplx* v) {
  for (int l = 0; l <= L; ++l) {
    v[idx(l, 0)] = a[idx(l, 0)];
    for (int m = 1; m <= l; ++m) {
      v[idx(l, m)] = cplx(a[idx(l, m)], -a[idx(l, -m)]) * 0.5;
      v[idx(l, -m)] = std::conj(v[idx(l, m)]);
    }
  }
}
void from_complex(int L, const cplx* v, double* a) {
  for (int l = 0; l <= L; ++l) {
    a[idx(l, 0)] = v[idx(l, 0)].real();
    for (int m = 1; m <= l; ++m) {
      a[idx(l, m)] = 2.0 * v[idx(l, m)].real();
      a[idx(l, -m)] = -2.0 * v[idx(l, m)].imag();
    }
  }
}

}  // namespace

void eval_surface(int L, const Vec3& d, double* out) { eval_scaled(L, d, out, 0); }
void eval_regular(int L, const Vec3& x, double* out) { eval_scaled(L, x, out, 1); }
void eval_irregular(int L, const Vec3& x, double* out) { eval_scaled(L, x, out, 2); }

void gradient(int L, const double* a, double* gx, double* gy, double* gz) {
  const int n = ncoef(L);
  std::vector<cplx> v(n), dx(n, 0.0), dy(n, 0.0), dz(n, 0.0);
  to_complex(L, a, v.data());
  for (int l = 1; l <= L; ++l) {
    for (int mu = -l; mu <= l; ++mu) {
      cplx c = v[idx(l, mu)];
      if (c == 0.0) continue;
      // d/dz Sc(l,mu) = sqrt(l^2 - mu^2) Sc(l-1, mu)
      if (std::abs(mu) <= l - 1) dz[idx(l - 1, mu)] += c * std::sqrt(double(l * l - mu * mu));
      // d+ = dx + i dy raises mu, d- = dx - i dy lowers mu.
      cplx plus = 0.0, minus = 0.0;
      int up = mu + 1, dn = mu - 1;
      if (std::abs(up) <= l - 1) {
        double f = std::sqrt(double((l - mu) * (l - mu - 1)));
        plus = c * (mu >= 0 ? -f : f);
        dx[idx(l - 1, up)] += 0.5 * plus;
        dy[idx(l - 1, up)] += cplx(0.5 * plus.imag(), -0.5 * plus.real());  // plus / 2i
      }
      if (std::abs(dn) <= l - 1) {
        double f = std::sqrt(double((l + mu) * (l + mu - 1)));
        minus = c * (mu >= 1 ? f : -f);
        dx[idx(l - 1, dn)] += 0.5 * minus;
        dy[idx(l - 1, dn)] -= cplx(0.5 * minus.imag(), -0.5 * minus.real());  // minus / 2i
      }
    }
  }
  from_complex(L, dx.data(), gx);
  from_complex(L, dy.data(), gy);
  from_complex(L, dz.data(), gz);
}

void rotation_generator(int L, const double* a, double* rx, double* ry, double* rz) {
  // G = r x grad = i Lop with Lop the angular-momentum operator; in the Sc basis
  // L+ Sc(l,mu) = s_+ sqrt((l-mu)(l+mu+1)) Sc(l,mu+1), s_+ = -1 for mu >= 0 else +1,
  // L- Sc(l,mu) = s_- sqrt((l+mu)(l-mu+1)) Sc(l,mu-1), s_- = -1 for mu >= 1 else +1,
  // Lz Sc(l,mu) = mu Sc(l,mu);  Gx = i(L+ + L-)/2, Gy = (L+ - L-)/2, Gz = i Lz.
  const int n = ncoef(L);
  std::vector<cplx> v(n), gx(n, 0.0), gy(n, 0.0), gz(n, 0.0);
  to_complex(L, a, v.data());
  for (int l = 1; l <= L; ++l) {
    for (int mu = -l; mu <= l; ++mu) {
      cplx c = v[idx(l, mu)];
      gz[idx(l, mu)] += cplx(-double(mu) * c.imag(), double(mu) * c.real());  // i mu c
      if (mu + 1 <= l) {
        cplx p = c * std::sqrt(double((l - mu) * (l + mu + 1))) * (mu >= 0 ? -1.0 : 1.0);
        gx[idx(l, mu + 1)] += cplx(-0.5 * p.imag(), 0.5 * p.real());  // i p / 2
        gy[idx(l, mu + 1)] += 0.5 * p;
      }
      if (mu - 1 >= -l) {
        cplx q = c * std::sqrt(double((l + mu) * (l - mu + 1))) * (mu >= 1 ? -1.0 : 1.0);
        gx[idx(l, mu - 1)] += cplx(-0.5 * q.imag(), 0.5 * q.real());  // i q / 2
        gy[idx(l, mu - 1)] -= 0.5 * q;
      }
    }
  }
  from_complex(L, gx.data(), rx);
  from_complex(L, gy.data(), ry);
  from_complex(L, gz.data(), rz);
}

double dot(int L, const double* a, const double* b) {
  double s = 0.0;
  for (int l = 0; l <= L; ++l)
    for (int m = -l; m <= l; ++m) s += norm_weight(l, m) * a[idx(l, m)] * b[idx(l, m)];
  return s;
}

}  // namespace agglo::es::sh
