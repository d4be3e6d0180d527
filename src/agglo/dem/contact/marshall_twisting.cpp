#include "agglo/dem/contact/marshall_twisting.hpp"

namespace agglo::dem::contact {

MarshallTwisting::MarshallTwisting(const ContactParams& p) : mu_(p.friction), gstar_(p.gstar()) {
  require(p.friction >= 0.0, "twisting", name, "friction coefficient mu", p.friction, ">= 0");
}

}  // namespace agglo::dem::contact
