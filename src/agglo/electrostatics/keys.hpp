#pragma once
// The [electrostatics] settings table (solver and coupling options, read by the electrostatics
// command and by charged impact cases), declared beside the solvers it names: the allowed values of
// electrostatics.solver are the names of the solver registry (registry.hpp), so a registered solver
// is selectable from a case file with no further edit.
#include "agglo/core/settings.hpp"
#include "agglo/electrostatics/bem/bem_solver.hpp"
#include "agglo/electrostatics/registry.hpp"

namespace agglo::es {

struct SolverKeys {
  settings::Table t{"electrostatics", "electrostatics, collide, vcrit, breakup", "electrostatic solver and coupling"};
  settings::Choice solver{
      t, {"electrostatics.solver", "", "solver of the induced charges"}, kDefaultSolver, &solver_names};
  // At most 1e6, as particles.permittivity (1e300 was accepted, issue 23 item 10).
  settings::Real medium_permittivity{
      t,
      {"electrostatics.medium_permittivity", "", "relative permittivity kappa_0 of the medium"},
      1.0,
      Range::open_closed(0.0, 1e6)};
  settings::Real min_gap{t,
                         {"electrostatics.min_gap", "", "g_min: electrostatic radius r_E = r / (1 + g_min/2)"},
                         0.01,
                         Range::closed_open(0.0, 1.0)};
  settings::Real update_fraction{t,
                                 {"electrostatics.update_fraction", "",
                                  "re-solve after a move of this fraction of the smallest electrostatic gap"},
                                 0.01,
                                 Range::open_closed(0.0, 1.0)};
  settings::Integer update_interval{
      t, {"electrostatics.update_interval", "steps", "also re-solve every N steps (0 = off)"}, 0, 0, 1000000000};
  // Error-controlled re-solves (impact/electrostatic_coupling.hpp): in place of update_fraction, a
  // motion threshold adapted at every solve to the measured error of the held forces.
  settings::Real force_tolerance{t,
                                 {"electrostatics.force_tolerance", "",
                                  "re-solve so that the held forces' relative error stays below this "
                                  "(adaptive; 0 = the fixed update_fraction)"},
                                 0.0,
                                 Range::closed_open(0.0, 1.0)};
  settings::Vector3 external_field{
      t, {"electrostatics.external_field", "V/m", "uniform external field"}, Vec3{0, 0, 0}, Range::any()};
  settings::Bool force_scale_chi{
      t, {"electrostatics.force_scale_chi", "", "scale forces by chi^(2/5) (reduced modulus)"}, false};
  settings::Choice hold{t,
                        {"electrostatics.hold", "", "forces between solves: held, corrected pairwise, or extrapolated from the last two solves"},
                        "constant",
                        {"constant", "pair_corrected", "extrapolated"}};
  settings::Integer max_degree{
      t, {"electrostatics.max_degree", "", "spectral: fixed degree (0 = adaptive)"}, 0, 0, 200};
  settings::Real target_accuracy{t,
                                 {"electrostatics.target_accuracy", "", "spectral: accuracy of the adaptive degree"},
                                 1e-4,
                                 Range::closed_open(1e-12, 1.0)};
  settings::Integer max_degree_limit{
      t, {"electrostatics.max_degree_limit", "", "spectral: highest adaptive degree"}, 80, 2, 200};
  settings::Choice far_field{t,
                             {"electrostatics.far_field", "",
                              "spectral: far field of the product, every pair directly (dense) or through an octree (fmm)"},
                             kFarFieldNames[0],
                             std::vector<std::string_view>(kFarFieldNames.begin(), kFarFieldNames.end())};
  // Read only when set (config.cpp), so that the resolved config of a case that does not name it is unchanged.
  settings::Choice preconditioner{
      t,
      {"electrostatics.preconditioner", "",
       "spectral: right preconditioner of GMRES; contact_low is the fast one, the others are measuring tools "
       "(docs/electrostatics.md)"},
      kPreconditionerNames[0],
      std::vector<std::string_view>(kPreconditionerNames.begin(), kPreconditionerNames.end())};
  // Read only when set, as preconditioner.
  settings::Integer preconditioner_steps{
      t,
      {"electrostatics.preconditioner_steps", "",
       "spectral, contact_low: Neumann steps of the preconditioner (3 saves an iteration at kappa_p = 15)"},
      kContactLowSteps,
      1,
      16};
  settings::Integer patches_per_sphere{t,
                                       {"electrostatics.patches_per_sphere", "", "bem: surface patches per sphere"},
                                       2000,
                                       bem::kMinPatchesPerSphere,
                                       10000000};
  settings::Real tolerance{
      t, {"electrostatics.tolerance", "", "bem, spectral: relative GMRES tolerance"}, 1e-6, Range::open(0.0, 1.0)};
  settings::Integer max_iterations{t, {"electrostatics.max_iterations", "", "most GMRES iterations"}, 200, 1, 100000};
  settings::Choice matvec{t, {"electrostatics.matvec", "", "bem: matrix-vector product"}, "fmm", {"fmm", "direct"}};
  settings::Integer fmm_order{
      t, {"electrostatics.fmm_order", "", "bem: FMM expansion order (0 = automatic)"}, 0, 0, 40};
  settings::Integer fmm_leaf_size{
      t, {"electrostatics.fmm_leaf_size", "", "bem: patches per FMM leaf box"}, 64, 1, 100000};
};

// The keys, listed in the settings catalogue (agglo config) before [[particles]].
const SolverKeys& solver_keys();

}  // namespace agglo::es
