#pragma once
// Base of the commands that run the impact experiment (collide, vcrit, breakup): one case format,
// parsed and validated the same way.
#include "agglo/impact/impact_case.hpp"
#include "agglo/run/command.hpp"

namespace agglo::run {

class ImpactCommand : public Command {
 public:
  void parse(Config& cfg) const override;
  // The parsed case (cfg has passed parse()).
  static impact::ImpactCase impact_case(Config& cfg);
};

}  // namespace agglo::run
