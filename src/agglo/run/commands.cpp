#include "agglo/run/commands.hpp"

namespace agglo::run {

const std::vector<const Command*>& all_commands() {
  static const std::vector<const Command*> list = {&collide_command(), &vcrit_command(), &breakup_command(),
                                                   &electrostatics_command(), &acoustic_command(),
                                                   &sectional_command(), &calibrate_command()};
  return list;
}

}  // namespace agglo::run
