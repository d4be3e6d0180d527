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

// name -> maker and traits; a null maker marks a built-in model (made by make_kernel_with<void>).
struct Entry {
  KernelMaker maker;
  Traits traits;
};
using Table = std::map<std::string, Entry, std::less<>>;

template <class... Ts>
void add_builtins(std::array<Table, kCategories>& tables, TypeList<Ts...>) {
  (tables[static_cast<std::size_t>(Ts::category)].emplace(Ts::name, Entry{nullptr, traits_of<Ts>()}), ...);
}

template <class... Ts>
const char* default_of(Category c, TypeList<Ts...>) {
  const char* name = "?";
  (void)((Ts::category == c && (name = Ts::name, true)) || ...);
  return name;
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

// The traits of the model named for `c`, if registered (the caller holds the lock).
std::optional<Traits> traits(const Registry& r, const ModelNames& m, Category c) {
  const Table& t = r.tables[static_cast<std::size_t>(c)];
  auto it = t.find(m[c]);
  if (it == t.end()) return std::nullopt;
  return it->second.traits;
}

}  // namespace

const char* default_model(Category c) { return default_of(c, DefaultModels{}); }

std::optional<Conflict> conflict(const ModelNames& m) {
  auto& r = registry();
  std::lock_guard lock(r.mutex);
  const auto tangential = traits(r, m, Category::tangential);
  if (!tangential || tangential->sliding_spring) return std::nullopt;
  for (Category c : {Category::rolling, Category::twisting}) {
    const auto need = traits(r, m, c);
    if (!need || !need->needs_sliding_spring) continue;
    std::string with;
    for (const auto& [name, entry] : r.tables[static_cast<std::size_t>(Category::tangential)])
      if (entry.traits.sliding_spring) with += (with.empty() ? "\"" : ", \"") + name + "\"";
    return Conflict{c, fmt::format("the {} model \"{}\" needs a tangential model with a sliding spring ({}), not "
                                   "\"{}\"", category_name(c), m[c], with, m.tangential)};
  }
  return std::nullopt;
}

std::vector<std::string> names(Category c) {
  auto& r = registry();
  std::lock_guard lock(r.mutex);
  std::vector<std::string> out;
  for (const auto& [name, maker] : r.tables[static_cast<std::size_t>(c)]) out.push_back(name);
  return out;
}

bool add_model(Category c, const std::string& name, KernelMaker maker, Traits traits) {
  auto& r = registry();
  std::lock_guard lock(r.mutex);
  if (!r.tables[static_cast<std::size_t>(c)].emplace(name, Entry{maker, traits}).second)
    throw std::logic_error(fmt::format("contact {} model \"{}\" is registered twice", category_name(c), name));
  return true;
}

KernelPtr make_kernel(const ModelNames& chosen, const std::vector<ContactParams>& p) {
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
      if (!it->second.maker) continue;
      if (owner)
        throw ConfigError(fmt::format("contact models \"{}\" ({}) and \"{}\" ({}) are both registered outside "
                                      "builtin_models.hpp and cannot be combined; list one of them there",
                                      chosen[*owner], category_name(*owner), chosen[c], category_name(c)));
      maker = it->second.maker;
      owner = c;
    }
  }
  if (const auto c = conflict(chosen)) throw ConfigError(c->rule);
  return maker(chosen, p);
}

}  // namespace agglo::dem::contact
