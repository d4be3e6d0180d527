#include "agglo/run/commands.hpp"

#include "agglo/acoustics/kernels/keys.hpp"
#include "agglo/dem/contact/settings.hpp"
#include "agglo/electrostatics/keys.hpp"

namespace agglo::run {

const std::vector<const Command*>& all_commands() {
  // The settings tables the engines declare beside their models join the catalogue (agglo config).
  static const bool tables = (dem::contact::contact_settings(), es::solver_keys(), acoustics::kernel_keys(), true);
  (void)tables;
  static const std::vector<const Command*> list = {&collide_command(), &vcrit_command(), &breakup_command(),
                                                   &electrostatics_command(), &acoustic_command(),
                                                   &sectional_command(), &calibrate_command(),
                                                   &aggregate_command(), &outcomes_command()};
  return list;
}

}  // namespace agglo::run
