#include "agglo/dem/contact/registry.hpp"

#include <array>
#include <fmt/format.h>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>

#include "agglo/core/error.hpp"

namespace agglo::dem::contact {

namespace {

// name -> maker; a null maker marks a built-in model (made by make_kernel_with<void>).
using Table = std::map<std::string, KernelMaker, std::less<>>;

template <class... Ts>
void add_builtins(std::array<Table, kCategories>& tables, TypeList<Ts...>) {
  (tables[static_cast<std::size_t>(Ts::category)].emplace(Ts::name, nullptr), ...);
}

struct Registry {
  Registry() { add_builtins(tables, BuiltinModels{}); }
  std::mutex mutex;
  std::array<Table, kCategories> tables;
};

Registry& registry() {
  static Registry r;
  return r;
}

constexpr std::array<Category, kCategories> kAll{Category::normal, Category::damping, Category::tangential,
                                                 Category::rolling, Category::twisting};

}  // namespace

std::vector<std::string> names(Category c) {
  auto& r = registry();
  std::lock_guard lock(r.mutex);
  std::vector<std::string> out;
  for (const auto& [name, maker] : r.tables[static_cast<std::size_t>(c)]) out.push_back(name);
  return out;
}

bool add_model(Category c, const std::string& name, KernelMaker maker) {
  auto& r = registry();
  std::lock_guard lock(r.mutex);
  if (!r.tables[static_cast<std::size_t>(c)].emplace(name, maker).second)
    throw std::logic_error(fmt::format("contact {} model \"{}\" is registered twice", category_name(c), name));
  return true;
}

KernelPtr make_kernel(const ModelNames& chosen, const ContactParams& p) {
  KernelMaker maker = &make_kernel_with<void>;
  std::optional<Category> owner;  // category of the model registered outside the built-in list
  {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    for (Category c : kAll) {
      const Table& t = r.tables[static_cast<std::size_t>(c)];
      auto it = t.find(chosen[c]);
      if (it == t.end()) {
        std::string known;
        for (const auto& entry : t) known += (known.empty() ? "\"" : ", \"") + entry.first + "\"";
        throw ConfigError(fmt::format("unknown contact {} model \"{}\" (known: {})", category_name(c), chosen[c],
                                      known));
      }
      if (!it->second) continue;
      if (owner)
        throw ConfigError(fmt::format("contact models \"{}\" ({}) and \"{}\" ({}) are both registered outside "
                                      "builtin_models.hpp and cannot be combined; list one of them there",
                                      chosen[*owner], category_name(*owner), chosen[c], category_name(c)));
      maker = it->second;
      owner = c;
    }
  }
  return maker(chosen, p);
}

}  // namespace agglo::dem::contact
