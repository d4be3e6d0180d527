// Checkpoint state of a collision run (impact_state.hpp): ImpactRun::state / restore.
#include "agglo/impact/impact_state.hpp"

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/impact/electrostatic_coupling.hpp"
#include "agglo/impact/impact_run.hpp"

namespace agglo::impact {

ImpactState ImpactRun::state() const {
  ImpactState s;
  s.speed = speed_;
  s.dem = sys_.state();
  if (const auto* ef = dynamic_cast<const ElectrostaticForce*>(es_.get())) {
    s.has_coupling = true;
    s.coupling = ef->state();
  }
  if (rec_) s.recorder = *rec_;
  s.progress = at_;
  s.launch = launch_agg_;
  return s;
}

void ImpactRun::restore(const ImpactState& s) {
  auto* ef = dynamic_cast<ElectrostaticForce*>(es_.get());
  if (s.dem.particles.size() != sys_.particles().size() || s.launch.size() != n_agg_ || s.has_coupling != (ef != nullptr) ||
      s.speed != speed_)
    throw ConfigError(fmt::format("collision state of {} particles at {} m/s (electrostatics {}) does not belong to "
                                  "this case ({} particles at {} m/s, electrostatics {})",
                                  s.dem.particles.size(), s.speed, s.has_coupling ? "on" : "off",
                                  sys_.particles().size(), speed_, ef ? "on" : "off"));
  sys_.restore(s.dem);
  if (ef) ef->restore(s.coupling);
  if (rec_) *rec_ = s.recorder;
  at_ = s.progress;
  set_launch(s.launch);
}

}  // namespace agglo::impact
