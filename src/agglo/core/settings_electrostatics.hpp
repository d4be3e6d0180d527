#pragma once
// Settings tables of the electrostatics: [[particles]] (explicit spheres, read by
// the electrostatics command and by impact cases with agglomerate.shape = "list") and the
// electrostatics command's [output].
#include "agglo/core/settings.hpp"

namespace agglo::settings {

struct ElectrostaticsSettings {
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

  std::vector<const Table*> tables() const { return {&particles.t, &output.t}; }
};

const ElectrostaticsSettings& electrostatics_settings();

}  // namespace agglo::settings
