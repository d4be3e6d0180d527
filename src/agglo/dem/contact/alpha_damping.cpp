#include "agglo/dem/contact/alpha_damping.hpp"

namespace agglo::dem::contact {

double damping_alpha(double e) {
  return 1.2728 - 4.2783 * e + 11.087 * e * e - 22.348 * std::pow(e, 3) + 27.467 * std::pow(e, 4) -
         18.022 * std::pow(e, 5) + 4.8218 * std::pow(e, 6);
}

AlphaDamping::AlphaDamping(const ContactParams& p) : alpha_(damping_alpha(p.restitution)) {
  require(p.restitution > 0.0 && p.restitution <= 1.0, "damping", name, "restitution coefficient e", p.restitution,
          "in (0, 1]");
}

}  // namespace agglo::dem::contact
