#pragma once
// Collision outcomes (MODEL C.5; seed section 2.4, eqs. 13-14, 22-24).
//  - any pair with a pure droplet: coalescence;
//  - solid-solid ("dry"): coalesce iff |G.n| <= v_cr,dry (Sgrott & Sommerfeld 2019, eq. 13)
//      v_cr,dry = A sqrt(1-e^2) / (pi d_min z0^2 e^2 sqrt(6 p_c rho_min (1 + d_min/d_max)));
//  - solid-mixed, mixed-mixed ("wet"): coalesce iff |G.n| <= v_cr,wet (Ennis 1991, eq. 14)
//      v_cr,wet = 9 mu_l (d_i+d_j) / (8 rho_s d_i d_j) (1 + 1/e) ln(delta/h_a);
//  - otherwise hard-sphere rebound with friction (eqs. 22-23); wet pairs use
//      e_wet = e - 9 mu_l (d_i+d_j)(1+e) ln(delta/h_a) / (8 rho_s d_i d_j |G.n|)   (eq. 24).
// G = v_i - v_j, n = unit vector from i to j at contact (approaching: G.n > 0).
#include "agglo/core/vec3.hpp"

namespace agglo::acoustics {

enum class PairType { droplet, dry, wet };

struct OutcomeParams {
  bool always_coalesce = false;   // test kernels: every collision coalesces
  double hamaker = 1e-19;         // A [J]
  double z0 = 4e-10;              // minimum contact distance [m]
  double contact_pressure = 3e8;  // p_c [Pa]
  double restitution = 0.6;       // e
  double friction = 0.2;          // f_p
  double liquid_viscosity = 8.9e-4;  // mu_l [Pa s]
  double film_ratio = 10.0;       // delta / h_a
  double solid_density = 2500.0;  // rho_s in eqs. 14, 24 [kg/m^3]
  bool energy_compensation = true;// seed eq. 30
};

double critical_velocity_dry(const OutcomeParams& o, double di, double dj, double rhoi, double rhoj);
double critical_velocity_wet(const OutcomeParams& o, double di, double dj);
double wet_restitution(const OutcomeParams& o, double di, double dj, double gn);

// Post-collision velocities of an equal-weight hard-sphere pair (eqs. 22-23), masses mi, mj,
// restitution e, friction f. n must be a unit vector with G.n > 0.
void hard_sphere_rebound(const Vec3& vi, const Vec3& vj, double mi, double mj, const Vec3& n, double e, double f,
                         Vec3& vi_out, Vec3& vj_out);

}  // namespace agglo::acoustics
