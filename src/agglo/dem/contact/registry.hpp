#pragma once
// Contact sub-models by name, one registry per category (after the granular sub-model styles of
// LAMMPS). A sub-model is a small class as described in sub_model.hpp. Built-in models are listed in
// builtin_models.hpp; a model defined anywhere else (a test, an application) registers with one line
//   const bool registered = agglo::dem::contact::register_model<MyModel>();
// Selecting a combination compiles nothing at run time: every registration instantiates the pair loop
// for its model with each built-in model of the other categories, so a registered model combines
// with all built-ins, but two models registered outside the built-in list cannot be combined.
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "agglo/dem/contact/builtin_models.hpp"
#include "agglo/dem/contact/pair_kernel.hpp"
#include "agglo/dem/contact/settings.hpp"

namespace agglo::dem::contact {

using KernelPtr = std::shared_ptr<const ContactKernel>;
using KernelMaker = KernelPtr (*)(const ModelNames&, const std::vector<ContactParams>&);

// The pair loop for the named models, one set of sub-models per entry of `p` (material pairs). Throws ConfigError naming the category, the unknown name and
// the registered ones, the conflict() of the combination, or the two non-built-in models that cannot
// be combined.
KernelPtr make_kernel(const ModelNames& names, const std::vector<ContactParams>& p);

// What a model declares about the models it combines with (sub_model.hpp); absent members are false.
struct Traits {
  bool sliding_spring = false;        // tangential: keeps a sliding spring
  bool needs_sliding_spring = false;  // rolling, twisting: only with a tangential model that keeps one
};

template <class M>
constexpr Traits traits_of() {
  Traits t;
  if constexpr (requires { M::sliding_spring; }) t.sliding_spring = M::sliding_spring;
  if constexpr (requires { M::needs_sliding_spring; }) t.needs_sliding_spring = M::needs_sliding_spring;
  return t;
}

// Registers `maker` as (category, name); throws std::logic_error if the name is taken. Returns true.
bool add_model(Category c, const std::string& name, KernelMaker maker, Traits traits);

namespace detail {

template <class... Chosen>
KernelPtr build(TypeList<Chosen...>, const ModelNames&, const std::vector<ContactParams>& p) {
  return std::make_shared<const PairKernel<Chosen...>>(p);
}

// Picks the type named for the next category from its list, then recurses (null if none matches).
template <class... Chosen, class... Ts, class... Lists>
KernelPtr build(TypeList<Chosen...>, const ModelNames& names, const std::vector<ContactParams>& p, TypeList<Ts...>,
                Lists... rest) {
  const std::string& want = names[static_cast<Category>(sizeof...(Chosen))];
  KernelPtr k;
  (void)((want == Ts::name && (k = build(TypeList<Chosen..., Ts>{}, names, p, rest...), true)) || ...);
  return k;
}

// The candidates of category C: `Model` alone if it belongs to C, else the built-ins of C.
template <Category C, class Model>
constexpr auto candidates() {
  if constexpr (!std::is_void_v<Model>) {
    if constexpr (Model::category == C) return TypeList<Model>{};
    else return of_category<C>(BuiltinModels{});
  } else {
    return of_category<C>(BuiltinModels{});
  }
}

}  // namespace detail

// Kernel maker for combinations of `Model` (void: none) with the built-in models.
template <class Model>
KernelPtr make_kernel_with(const ModelNames& names, const std::vector<ContactParams>& p) {
  using detail::candidates;
  return detail::build(TypeList<>{}, names, p, candidates<Category::normal, Model>(),
                       candidates<Category::damping, Model>(), candidates<Category::tangential, Model>(),
                       candidates<Category::rolling, Model>(), candidates<Category::twisting, Model>());
}

template <class Model>
bool register_model() {
  declare_coefficients(coefficients_of<Model>());
  return add_model(Model::category, Model::name, &make_kernel_with<Model>, traits_of<Model>());
}

}  // namespace agglo::dem::contact
