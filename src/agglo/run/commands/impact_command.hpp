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
  // The parsed case (cfg has passed parse()).
  static impact::ImpactCase impact_case(Config& cfg);
  // The agglomerate relaxed under electrostatics (impact::relaxed_agglomerate), its progress reported
  // to ctx as the task "relaxation".
  static dem::Particles relaxed_target(const impact::ImpactCase& c, const RunContext& ctx);
};

}  // namespace agglo::run
