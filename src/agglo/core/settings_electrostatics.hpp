#pragma once
// Settings tables of the electrostatics: [electrostatics] (solver and coupling options, read by the
// electrostatics command and by charged impact cases), [[particles]] (explicit spheres, read by
// the electrostatics command and by impact cases with agglomerate.shape = "list") and the
// electrostatics command's [output].
#include "agglo/core/settings.hpp"

namespace agglo::settings {

struct ElectrostaticsSettings {
  struct Solver {
    Table t{"electrostatics", "electrostatics, collide, vcrit, breakup", "electrostatic solver and coupling"};
    Choice solver{t, {"electrostatics.solver", "", "solver of the induced charges"}, "spectral",
                  {"coulomb", "spectral", "bem"}};
    // At most 1e6, as particles.permittivity (1e300 was accepted, issue 23 item 10).
    Real medium_permittivity{t, {"electrostatics.medium_permittivity", "", "relative permittivity kappa_0 of the medium"},
                             1.0, Range::open_closed(0.0, 1e6)};
    Real min_gap{t, {"electrostatics.min_gap", "", "g_min: electrostatic radius r_E = r / (1 + g_min/2)"}, 0.01,
                 Range::closed_open(0.0, 1.0)};
    Real update_fraction{t,
                         {"electrostatics.update_fraction", "",
                          "re-solve after a move of this fraction of the smallest electrostatic gap"},
                         0.01, Range::open_closed(0.0, 1.0)};
    Integer update_interval{t, {"electrostatics.update_interval", "steps", "also re-solve every N steps (0 = off)"},
                            0, 0, 1000000000};
    Vector3 external_field{t, {"electrostatics.external_field", "V/m", "uniform external field"}, Vec3{0, 0, 0},
                           Range::any()};
    Bool force_scale_chi{t, {"electrostatics.force_scale_chi", "", "scale forces by chi^(2/5) (reduced modulus)"},
                         false};
    Choice hold{t, {"electrostatics.hold", "", "forces between solves: held, or corrected pairwise"}, "constant",
                {"constant", "pair_corrected"}};
    Integer max_degree{t, {"electrostatics.max_degree", "", "spectral: fixed degree (0 = adaptive)"}, 0, 0, 200};
    Real target_accuracy{t, {"electrostatics.target_accuracy", "", "spectral: accuracy of the adaptive degree"},
                         1e-4, Range::closed_open(1e-12, 1.0)};
    Integer max_degree_limit{t, {"electrostatics.max_degree_limit", "", "spectral: highest adaptive degree"}, 80, 2,
                             200};
    // Lower bound 12 = bem::kMinPatchesPerSphere (the BEM solver's smallest usable mesh).
    Integer patches_per_sphere{t, {"electrostatics.patches_per_sphere", "", "bem: surface patches per sphere"},
                               2000, 12, 10000000};
    Real tolerance{t, {"electrostatics.tolerance", "", "bem, spectral: relative GMRES tolerance"}, 1e-6,
                   Range::open(0.0, 1.0)};
    Integer max_iterations{t, {"electrostatics.max_iterations", "", "most GMRES iterations"}, 200, 1, 100000};
    Choice matvec{t, {"electrostatics.matvec", "", "bem: matrix-vector product"}, "fmm", {"fmm", "direct"}};
    Integer fmm_order{t, {"electrostatics.fmm_order", "", "bem: FMM expansion order (0 = automatic)"}, 0, 0, 40};
    Integer fmm_leaf_size{t, {"electrostatics.fmm_leaf_size", "", "bem: patches per FMM leaf box"}, 64, 1, 100000};
  } solver;

  struct Particles {
    Table t{"particles", "electrostatics, collide, vcrit, breakup",
            "explicit spheres (impact cases: agglomerate shape list)", true};
    Vector3 position{t, {"particles.position", "m", "centre"}, std::nullopt, Range::closed(-1e3, 1e3)};
    Real radius{t, {"particles.radius", "m", "radius"}, std::nullopt, Range::open_closed(0.0, 0.1)};
    Real charge{t, {"particles.charge", "C", "charge"}, 0.0, Range::closed(-1e-3, 1e-3)};
    Real permittivity{t, {"particles.permittivity", "", "relative permittivity kappa_p"}, 1.0, Range::open_closed(0.0, 1e6)};
    Text material{t, {"particles.material", "", "impact cases: material, default or a [[materials]] name",
                                "default"},
                  std::nullopt};
  } particles;

  struct Output {
    Table t{"output", "electrostatics", "outputs of the electrostatics command"};
    Bool surface{t, {"output.surface", "", "write surface.vtu (surface charge, binary VTK)"}, true};
  } output;

  std::vector<const Table*> tables() const { return {&solver.t, &particles.t, &output.t}; }
};

const ElectrostaticsSettings& electrostatics_settings();

}  // namespace agglo::settings
