#pragma once
// Material and contact settings of the adhesive DEM (docs/model.md §A.2), as read from the config.
// The contact law itself is assembled from named sub-models (normal, damping, tangential, rolling,
// twisting; src/agglo/dem/contact/), named by `models`; the other fields are their coefficients.
#include <map>
#include <string>

#include "agglo/dem/contact/coefficient.hpp"
#include "agglo/dem/contact/model_names.hpp"

namespace agglo::dem {

enum class BreakRule { marshall, lammps };

struct ContactParams {
  double youngs_modulus = 1.0e9;   // E [Pa]
  double poisson_ratio = 0.33;     // nu [-]
  double surface_energy = 0.01;    // gamma [J/m^2]
  double restitution = 0.7;        // e in (0, 1]; alpha(e) damping
  double friction = 0.3;           // mu_F [-]
  contact::ModelNames models;      // the sub-model of each category ([contact] keys)
  double rolling_angle = 0.01;     // critical rolling angle theta_crit [rad]
  BreakRule break_rule = BreakRule::marshall;
  std::map<std::string, double, std::less<>> declared;  // coefficients sub-models declare, by key
  // > 0: E* and G* of a pair of two different materials (material.hpp), used by estar() and gstar().
  double pair_estar = 0.0, pair_gstar = 0.0;

  // The value of a declared coefficient: as read from the case, else its default.
  double value(const contact::Coefficient& c) const;

  double estar() const;  // like materials: E / (2 (1 - nu^2)); else pair_estar
  double gstar() const;  // like materials: G / (2 (2 - nu)), G = E / (2 (1 + nu)); else pair_gstar
};

}  // namespace agglo::dem
