#include <stdexcept>

#include "agglo/collision/experiment.hpp"
#include "agglo/core/error.hpp"

namespace agglo::collision {

std::unique_ptr<dem::ExternalForce> make_electrostatic_force(const CollisionCase&) {
  throw ConfigError("electrostatics coupling is not available in this build yet");
}

}  // namespace agglo::collision
