#include "agglo/dem/contact/seed_friction.hpp"

namespace agglo::dem::contact {

SeedFriction::SeedFriction(const ContactParams& p) : mu_(p.friction) {
  require(p.friction >= 0.0, "tangential", name, "friction coefficient mu", p.friction, ">= 0");
}

}  // namespace agglo::dem::contact
