#pragma once
// A coefficient a contact sub-model declares beside its class, so that a new model needs no edit
// elsewhere: one [contact] key with its unit, default, closed range and meaning,
//   static constexpr Coefficient coefficients[] = {{"contact.my_coefficient", "unit", "meaning", 0.0, 0.0, 1.0}};
// The [contact] table (settings.hpp) declares the key for every registered model, the case parser
// reads it into ContactParams::declared, and the model's constructor takes its value with
// p.value(coefficients[0]). docs/config.md lists the keys of the models built into agglo.
#include <string_view>

namespace agglo::dem::contact {

struct Coefficient {
  std::string_view key;      // dotted config key, "contact.<name>"
  std::string_view unit;     // "" for dimensionless
  std::string_view meaning;  // one line, for docs/config.md
  double def = 0.0;          // default
  double lo = 0.0, hi = 0.0;  // allowed range [lo, hi]
};

}  // namespace agglo::dem::contact
