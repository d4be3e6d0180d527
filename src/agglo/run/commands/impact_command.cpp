#include "agglo/run/commands/impact_command.hpp"

namespace agglo::run {

void ImpactCommand::parse(Config& cfg) const {
  (void)impact::parse_impact_case(cfg);
  cfg.check_unknown_keys();
}

impact::ImpactCase ImpactCommand::impact_case(Config& cfg) { return impact::parse_impact_case(cfg); }

dem::Particles ImpactCommand::relaxed_target(const impact::ImpactCase& c, const RunContext& ctx) {
  return impact::relaxed_agglomerate(c, [&ctx](double f, double t) { ctx.report().progress("relaxation", f, t); });
}

}  // namespace agglo::run
