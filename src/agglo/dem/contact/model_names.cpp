#include "agglo/dem/contact/model_names.hpp"

namespace agglo::dem::contact {

const char* category_name(Category c) {
  switch (c) {
    case Category::normal: return "normal";
    case Category::damping: return "damping";
    case Category::tangential: return "tangential";
    case Category::rolling: return "rolling";
    case Category::twisting: return "twisting";
  }
  return "?";
}

std::string& ModelNames::operator[](Category c) {
  switch (c) {
    case Category::normal: return normal;
    case Category::damping: return damping;
    case Category::tangential: return tangential;
    case Category::rolling: return rolling;
    case Category::twisting: break;
  }
  return twisting;
}

const std::string& ModelNames::operator[](Category c) const { return const_cast<ModelNames&>(*this)[c]; }

}  // namespace agglo::dem::contact
