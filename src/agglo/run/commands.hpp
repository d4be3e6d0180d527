#pragma once
// The commands of agglo, one file each in run/commands/. Adding a command: a class implementing
// run::Command in its own file plus one line in commands.cpp.
#include <vector>

#include "agglo/run/command.hpp"

namespace agglo::run {

const Command& collide_command();
const Command& vcrit_command();
const Command& breakup_command();
const Command& electrostatics_command();
const Command& acoustic_command();
const Command& sectional_command();
const Command& calibrate_command();
const Command& aggregate_command();
const Command& outcomes_command();

// Every command, in the order of `agglo --help`.
const std::vector<const Command*>& all_commands();

}  // namespace agglo::run
