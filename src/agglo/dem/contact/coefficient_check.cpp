#include "agglo/dem/contact/coefficient_check.hpp"

#include <fmt/format.h>

#include "agglo/core/error.hpp"

namespace agglo::dem::contact {

void require(bool ok, std::string_view category, std::string_view model, std::string_view quantity, double value,
             std::string_view requirement) {
  if (ok) return;
  throw ConfigError(fmt::format("contact {} model \"{}\": {} = {} must be {}", category, model, quantity, value,
                                requirement));
}

}  // namespace agglo::dem::contact
