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

ModelNames model_names(const ContactParams& p) {
  ModelNames m;
  m.damping = p.damping ? "alpha" : "none";
  m.tangential = p.tangential == TangentialModel::seed ? "seed" : "marshall";
  m.rolling = p.rolling ? "marshall" : "none";
  m.twisting = p.twisting ? "marshall" : "none";
  return m;
}

}  // namespace agglo::dem::contact
