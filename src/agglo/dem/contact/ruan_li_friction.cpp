#include "agglo/dem/contact/ruan_li_friction.hpp"

namespace agglo::dem::contact {

RuanLiFriction::RuanLiFriction(const ContactParams& p) : mu_(p.friction) {
  require(p.friction >= 0.0, "tangential", name, "friction coefficient mu", p.friction, ">= 0");
}

}  // namespace agglo::dem::contact
