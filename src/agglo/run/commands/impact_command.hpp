#pragma once
// Base of the commands that run the impact experiment (collide, vcrit, breakup): one case format,
// parsed and validated the same way.
#include "agglo/impact/experiment.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/run/command.hpp"

namespace agglo::run {

class ImpactCommand : public Command {
 public:
  void parse(Config& cfg) const override;
  // 2e-8 s per weighted particle-step: collide of the seed-000 tetrahedron at kappa_p = 2.5 on one
  // thread, 27.7 s of CPU for 1.41e9 estimated weighted particle-steps (the neutral one 1.5e-8).
  double seconds_per_step(Config&) const override { return 2e-8; }
  // The parsed case (cfg has passed parse()).
  static impact::ImpactCase impact_case(Config& cfg);
  // The agglomerate relaxed under electrostatics (impact::relaxed_agglomerate), its progress reported
  // to ctx as the task "relaxation".
  static dem::Particles relaxed_target(const impact::ImpactCase& c, const RunContext& ctx);
};

}  // namespace agglo::run
