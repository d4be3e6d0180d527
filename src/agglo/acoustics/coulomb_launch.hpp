#pragma once
// The Coulomb work before a charged outcome table's launch gap (docs/acoustics.md §1.7 "Coulomb work"):
// the table's v_n is the normal speed the pair has at the DEM's launch separation s (outcome_table.hpp
// kLaunchGapAttribute), while the DSMC meets its pair at the far-field relative normal speed v_n,inf. With
// point charges q_i, q_j [C] in a medium of relative permittivity kappa_0, energy conservation of the
// normal motion of the reduced mass mu = m_i m_j / (m_i + m_j) [kg] from infinity to s gives
//   v_launch^2 = v_n,inf^2 - 2 U(s) / mu,   U(s) = q_i q_j / (4 pi eps_0 kappa_0 s),
//   s = r_i + r_j + g min(r_i, r_j),  r = d / 2 (volume-equivalent) [m],
// g the launch gap in units of the smaller (target) sphere's radius. v_launch^2 < 0: like charges turn the
// pair back before the launch separation (it never touches).
namespace agglo::acoustics {

// v_launch [m/s] of the formula above, or -1 when the pair is turned back (v_launch^2 < 0).
double coulomb_launch_speed(double vn, double qi, double qj, double mi, double mj, double di, double dj, double gap,
                            double kappa0);

}  // namespace agglo::acoustics
