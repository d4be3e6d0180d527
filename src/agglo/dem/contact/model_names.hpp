#pragma once
// A contact law is one sub-model per category, each chosen by name (docs/dem.md, "Contact
// sub-models"). The names a ContactParams selects are those of the config keys contact.tangential,
// contact.rolling, contact.twisting and contact.damping.
#include <cstddef>
#include <string>
#include <vector>

#include "agglo/dem/contact_params.hpp"

namespace agglo::dem::contact {

enum class Category { normal, damping, tangential, rolling, twisting };
inline constexpr std::size_t kCategories = 5;

const char* category_name(Category c);  // "normal", "damping", ...

struct ModelNames {
  std::string normal = "jkr";
  std::string damping = "alpha";
  std::string tangential = "seed";
  std::string rolling = "none";
  std::string twisting = "none";

  const std::string& operator[](Category c) const;
  std::string& operator[](Category c);
};

// Registered names of a category, sorted: the allowed values of its config key (registry.cpp).
std::vector<std::string> names(Category c);

// normal "jkr"; damping "alpha" | "none" (contact.damping); tangential "seed" | "marshall"
// (contact.tangential); rolling and twisting "marshall" | "none" (contact.rolling, contact.twisting).
ModelNames model_names(const ContactParams& p);

}  // namespace agglo::dem::contact
