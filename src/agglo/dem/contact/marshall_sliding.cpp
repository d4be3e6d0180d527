#include "agglo/dem/contact/marshall_sliding.hpp"

namespace agglo::dem::contact {

MarshallSliding::MarshallSliding(const ContactParams& p) : mu_(p.friction), gstar_(p.gstar()) {
  require(p.friction >= 0.0, "tangential", name, "friction coefficient mu", p.friction, ">= 0");
}

}  // namespace agglo::dem::contact
