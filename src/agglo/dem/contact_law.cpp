#include "agglo/dem/contact_law.hpp"

#include "agglo/dem/contact/registry.hpp"

namespace agglo::dem {

ContactLaw::ContactLaw(const ContactParams& p) : ContactLaw(p, p.models) {}

ContactLaw::ContactLaw(const ContactParams& p, const contact::ModelNames& names)
    : names_(names), kernel_(contact::make_kernel(names, {p})) {}

ContactLaw::ContactLaw(const MaterialPairs& pairs, const contact::ModelNames& names)
    : names_(names), kernel_(contact::make_kernel(names, pairs.table)) {}

}  // namespace agglo::dem
