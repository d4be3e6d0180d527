#include "agglo/dem/contact/marshall_rolling.hpp"

namespace agglo::dem::contact {

MarshallRolling::MarshallRolling(const ContactParams& p) : theta_crit_(p.rolling_angle) {
  require(p.rolling_angle > 0.0, "rolling", name, "critical rolling angle", p.rolling_angle, "> 0 rad");
}

}  // namespace agglo::dem::contact
