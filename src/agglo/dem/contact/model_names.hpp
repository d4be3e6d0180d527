#pragma once
// A contact law is one sub-model per category, each chosen by name (docs/dem.md, "Contact
// sub-models"). The names are those the models declare (registry.hpp); a case selects them with the
// keys of its [contact] table (settings.hpp).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace agglo::dem::contact {

enum class Category { normal, damping, tangential, rolling, twisting };
inline constexpr std::size_t kCategories = 5;

const char* category_name(Category c);  // "normal", "damping", ...

// The model of category `c` used when none is named (DefaultModels in builtin_models.hpp).
const char* default_model(Category c);

struct ModelNames {
  std::string normal = default_model(Category::normal);
  std::string damping = default_model(Category::damping);
  std::string tangential = default_model(Category::tangential);
  std::string rolling = default_model(Category::rolling);
  std::string twisting = default_model(Category::twisting);

  const std::string& operator[](Category c) const;
  std::string& operator[](Category c);
};

// Registered names of a category, sorted: the allowed values of its config key (registry.cpp).
std::vector<std::string> names(Category c);

// A combination the chosen models do not allow (each model declares what it needs, sub_model.hpp):
// the category of the model that objects and the rule it states.
struct Conflict {
  Category category;
  std::string rule;
};
std::optional<Conflict> conflict(const ModelNames& m);

}  // namespace agglo::dem::contact
