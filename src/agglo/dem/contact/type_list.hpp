#pragma once
// Compile-time lists of sub-model types, filtered by category.
#include <type_traits>

#include "agglo/dem/contact/model_names.hpp"

namespace agglo::dem::contact {

template <class... Ts>
struct TypeList {};

template <class... A, class... B>
constexpr TypeList<A..., B...> operator+(TypeList<A...>, TypeList<B...>) {
  return {};
}

// The listed types whose `category` is C, in order.
template <Category C, class... Ts>
constexpr auto of_category(TypeList<Ts...>) {
  return (TypeList<>{} + ... + std::conditional_t<Ts::category == C, TypeList<Ts>, TypeList<>>{});
}

}  // namespace agglo::dem::contact
