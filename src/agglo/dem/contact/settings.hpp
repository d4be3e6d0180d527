#pragma once
// The [contact] settings table: the sub-model of each category, chosen by name, and the contact
// options. The allowed values of each model key are the names registered for its category
// (registry.hpp), so a model listed in builtin_models.hpp is selectable from a case file with no
// further edit. Former spellings still read (documented in docs/config.md): true/false for
// contact.damping (alpha/none), contact.rolling and contact.twisting (marshall/none), and the deprecated
// contact.tangential = "seed" for "ruan_li" (with a warning).
#include <deque>
#include <map>
#include <mutex>
#include <span>
#include <string>

#include "agglo/core/config.hpp"
#include "agglo/core/settings.hpp"
#include "agglo/core/settings_impact.hpp"
#include "agglo/dem/contact/coefficient.hpp"
#include "agglo/dem/contact/model_names.hpp"

namespace agglo::dem::contact {

struct ContactSettings {
  settings::Table t{"contact", settings::kImpactCommands, "contact force model"};
  settings::Choice tangential;
  settings::Choice rolling;
  settings::Choice twisting;
  settings::Real rolling_angle{t, {"contact.rolling_angle", "rad", "critical rolling angle theta_crit"}, 0.01,
                               Range::positive()};
  settings::Choice break_rule{t, {"contact.break_rule", "", "when a stretched adhesive contact breaks"}, "marshall",
                              {"marshall", "lammps"}};
  settings::Choice damping;

  ContactSettings();
  const settings::Choice& key(Category c) const;  // the key naming the model of c (none for normal)

  // The keys of the coefficients the registered models declare (coefficient.hpp), listed after the
  // keys above; a key declared by several models is declared once.
  void declare(std::span<const Coefficient> coefficients);
  std::map<std::string, double, std::less<>> read_declared(const ConfigSection& con) const;

 private:
  mutable std::mutex mutex_;
  std::deque<settings::Real> declared_;
};

// The table, listed by the settings catalogue after [material].
const ContactSettings& contact_settings();
// Declares the coefficient keys of a model registered outside builtin_models.hpp (register_model).
void declare_coefficients(std::span<const Coefficient> coefficients);

// The coefficients a model declares (empty if none).
template <class M>
constexpr std::span<const Coefficient> coefficients_of() {
  if constexpr (requires { M::coefficients; }) return M::coefficients;
  return {};
}

// The models a case's [contact] section names (the normal model is always the default). A combination
// the models do not allow (conflict()) is rejected with a one-line ConfigError on the key of the
// model that objects.
ModelNames read_models(const ConfigSection& con);

}  // namespace agglo::dem::contact
