#include "agglo/dem/contact/settings.hpp"

#include "agglo/core/settings_catalogue.hpp"
#include "agglo/dem/contact/builtin_models.hpp"

namespace agglo::dem::contact {

namespace {

template <Category C>
std::vector<std::string> names_of() {
  return names(C);
}

template <class... Ts>
void declare_builtins(ContactSettings& s, TypeList<Ts...>) {
  (s.declare(coefficients_of<Ts>()), ...);
}

ContactSettings& the_settings() {
  static ContactSettings s;
  static const bool listed = settings::add_table(s.t, settings::impact_settings().material.t);
  (void)listed;
  return s;
}

}  // namespace

ContactSettings::ContactSettings()
    : tangential{t,
                 {"contact.tangential", "", "tangential (sliding) force model"},
                 default_model(Category::tangential),
                 &names_of<Category::tangential>,
                 {.renamed = {{"seed", RuanLiFriction::name}}}},
      rolling{t,
              {"contact.rolling", "", "rolling resistance model"},
              default_model(Category::rolling),
              &names_of<Category::rolling>,
              {.if_true = MarshallRolling::name, .if_false = NoRolling::name}},
      twisting{t,
               {"contact.twisting", "", "twisting resistance model"},
               default_model(Category::twisting),
               &names_of<Category::twisting>,
               {.if_true = MarshallTwisting::name, .if_false = NoTwisting::name}},
      damping{t,
              {"contact.damping", "", "viscous damping model of the normal (and tangential) contact force"},
              default_model(Category::damping),
              &names_of<Category::damping>,
              {.if_true = AlphaDamping::name, .if_false = NoDamping::name}} {
  declare_builtins(*this, BuiltinModels{});
}

void ContactSettings::declare(std::span<const Coefficient> coefficients) {
  std::lock_guard lock(mutex_);
  for (const Coefficient& c : coefficients) {
    bool known = false;
    for (const auto& r : declared_) known = known || r.dotted() == c.key;
    if (!known) declared_.emplace_back(t, settings::Info{c.key, c.unit, c.meaning}, c.def, Range::closed(c.lo, c.hi));
  }
}

std::map<std::string, double, std::less<>> ContactSettings::read_declared(const ConfigSection& con) const {
  std::lock_guard lock(mutex_);
  std::map<std::string, double, std::less<>> out;
  for (const auto& r : declared_) out[std::string(r.dotted())] = r.read(con);
  return out;
}

const settings::Choice& ContactSettings::key(Category c) const {
  switch (c) {
    case Category::damping: return damping;
    case Category::tangential: return tangential;
    case Category::rolling: return rolling;
    case Category::twisting: return twisting;
    case Category::normal: break;
  }
  return tangential;
}

const ContactSettings& contact_settings() { return the_settings(); }

void declare_coefficients(std::span<const Coefficient> coefficients) { the_settings().declare(coefficients); }

ModelNames read_models(const ConfigSection& con) {
  const auto& k = contact_settings();
  ModelNames m;
  m.tangential = k.tangential.read(con);
  m.rolling = k.rolling.read(con);
  m.twisting = k.twisting.read(con);
  m.damping = k.damping.read(con);
  if (const auto c = conflict(m)) k.key(c->category).reject(con, c->rule);
  return m;
}

}  // namespace agglo::dem::contact
