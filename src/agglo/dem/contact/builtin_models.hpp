#pragma once
// The contact sub-models compiled into agglo: a model listed here is selectable by name and combines
// with every other listed model. Adding one = its header (+ .cpp) and one entry in this list.
#include "agglo/dem/contact/alpha_damping.hpp"
#include "agglo/dem/contact/jkr_normal.hpp"
#include "agglo/dem/contact/marshall_rolling.hpp"
#include "agglo/dem/contact/marshall_sliding.hpp"
#include "agglo/dem/contact/marshall_twisting.hpp"
#include "agglo/dem/contact/no_resistance.hpp"
#include "agglo/dem/contact/ruan_li_friction.hpp"
#include "agglo/dem/contact/type_list.hpp"

namespace agglo::dem::contact {

using BuiltinModels = TypeList<
    JkrNormal,                         // normal
    AlphaDamping, NoDamping,           // damping
    RuanLiFriction, MarshallSliding,   // tangential
    NoRolling, MarshallRolling,        // rolling
    NoTwisting, MarshallTwisting>;     // twisting

// The model of each category when a case names none (the default of its [contact] key).
using DefaultModels = TypeList<JkrNormal, AlphaDamping, RuanLiFriction, NoRolling, NoTwisting>;

}  // namespace agglo::dem::contact
