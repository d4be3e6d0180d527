#pragma once
// Test-side INDEPENDENT reference for two dielectric spheres on a common axis (no applied field):
// zonal Legendre expansion of each sphere's total surface charge density,
//   sigma_i(theta_i) = sum_n s_i^n P_n(cos theta_i),   n = 0..N,
// and BSL's projected equation for each sphere and degree l (docs/model.md §B.2 item 3, m = 0):
//   [(k0 (l+1) + k_i l)/(2l+1)] s_i^l - (k0 - k_i) (l / a_i) c_i^l = sigma_f,i delta_l0 ,
// where c_i^l = (2l+1)/2 \int phi_other(a_i, mu) P_l(mu) dmu / eps0 is the Legendre coefficient
// of the other sphere's potential on sphere i, obtained by Gauss-Legendre quadrature of the
// *directly summed* exterior multipole series of the other sphere (no translation formulas).
// Dense LU solve. Force on sphere 2 along +z by quadrature of kappa0 sigma_2 E_z(other) over its
// surface; energy 1/2 sum_i q_i <phi>_i. Different basis, re-expansion and force evaluation than
// the spectral solver, so agreement is a real check.
namespace agglo::es::testref {

struct TwoSphereInput {
  double a1 = 1, a2 = 1;        // radii [m]
  double t = 3;                 // centre distance [m] (sphere 1 at 0, sphere 2 at +t z)
  double k1 = 1, k2 = 1, k0 = 1;  // permittivities
  double q1 = 0, q2 = 0;        // free charges [C]
  int N = 60;                   // Legendre degree
  int Q = 0;                    // quadrature points (0: max(200, 3N))
};

struct TwoSphereResult {
  double fz2 = 0;     // force on sphere 2 along +z [N] (positive = repulsion)
  double fz1 = 0;     // force on sphere 1 along +z [N]
  double energy = 0;  // U = 1/2 \int phi sigma_f [J], self energies included
};

TwoSphereResult solve_two_spheres(const TwoSphereInput& in);

// BSL App. C: interaction energy of a point charge q at surface distance d from a neutral sphere
// of radius r0 and contrast kt = kappa_p / kappa_0 (in vacuum), series summed to convergence [J].
double point_charge_sphere_energy(double q, double d, double r0, double kt);

}  // namespace agglo::es::testref
