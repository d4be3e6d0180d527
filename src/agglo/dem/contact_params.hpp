#pragma once
// Material and contact settings of the adhesive DEM (docs/model.md §A.2), as read from the config.
// The contact law itself is assembled from named sub-models (normal, damping, tangential, rolling,
// twisting; src/agglo/dem/contact/); contact::model_names() maps the fields below to those names.
namespace agglo::dem {

enum class BreakRule { marshall, lammps };
enum class TangentialModel { seed, marshall };

struct ContactParams {
  double youngs_modulus = 1.0e9;   // E [Pa]
  double poisson_ratio = 0.33;     // nu [-]
  double surface_energy = 0.01;    // gamma [J/m^2]
  double restitution = 0.7;        // e in (0, 1]; alpha(e) damping
  double friction = 0.3;           // mu_F [-]
  TangentialModel tangential = TangentialModel::seed;
  bool rolling = false;            // Marshall rolling resistance
  bool twisting = false;           // Marshall twisting resistance
  double rolling_angle = 0.01;     // critical rolling angle theta_crit [rad]
  BreakRule break_rule = BreakRule::marshall;
  bool damping = true;             // switch normal/tangential damping off (analytic checks)

  double estar() const;  // like materials: E / (2 (1 - nu^2))
  double gstar() const;  // like materials: G / (2 (2 - nu)), G = E / (2 (1 + nu))
};

}  // namespace agglo::dem
