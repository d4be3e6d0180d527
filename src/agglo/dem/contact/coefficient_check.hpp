#pragma once
// Sub-models check the coefficients they own when they are constructed.
#include <string_view>

namespace agglo::dem::contact {

// Throws ConfigError "contact <category> model "<model>": <quantity> = <value> must be <requirement>"
// unless `ok`.
void require(bool ok, std::string_view category, std::string_view model, std::string_view quantity, double value,
             std::string_view requirement);

}  // namespace agglo::dem::contact
