#pragma once
// Composition of kernel mechanisms, written once: beta, bound and bound_cell of the set are the sums
// over the switched-on mechanisms, in the order of the type list (the summation order). Mechanisms are
// switched on by name when the set is built; the sums then test one precomputed flag per mechanism
// and call its (inlined) member, with no virtual call per pair.
// A mechanism M provides:
//   static constexpr std::string_view name;
//   M(const KernelSettings&, const Gas&, const Sound&);
//   KernelNeeds needs() const;
//   double beta(const SampleSet&, std::size_t i, std::size_t j, double r) const;   // [m^3/s]
//   double bound(const SampleSet&, std::size_t i, const CellBounds&) const;        // >= beta(i, j) for j in the cell
//   double bound_cell(const CellBounds&) const;                                    // >= bound(i) for i in the cell
//   double bound_pair(const CellBounds& a, const CellBounds& b) const;             // >= beta(i, j), i in a, j in b
//   optional: void prepare(CellBounds&) const;  // derived fields bound_pair reads, after the group's includes
//   optional: static constexpr bool standalone = true;     // selectable alone: kernels.model = name
//   optional: static constexpr bool brownian_term = true;  // the acoustic sum's Brownian term: kernels.brownian = name
//   optional: static constexpr bool compact_spheres_only = true;  // refused by cases with a fractal population
//             (structure.hpp: the others read d as the collision diameter and tau, C_c / d from the mobility one)
// The acoustic terms orthokinetic, acoustic_wake and radiation_pressure have a switch key each.
// The binned selection (binned.hpp) draws candidates of each mechanism separately: beta_of(k, ...) and
// bound_pair_of(k, ...) address the k-th switched-on mechanism.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "agglo/acoustics/kernels/cell_bounds.hpp"
#include "agglo/acoustics/kernels/settings.hpp"
#include "agglo/acoustics/sound.hpp"

namespace agglo::acoustics {

// Throws ConfigError naming the registered mechanisms (kernels.cpp).
[[noreturn]] void throw_unknown_mechanism(const std::string& name, const std::vector<std::string_view>& known);

template <class M>
constexpr bool declares_standalone() {
  if constexpr (requires { M::standalone; }) return M::standalone;
  return false;
}
template <class M>
constexpr bool declares_brownian_term() {
  if constexpr (requires { M::brownian_term; }) return M::brownian_term;
  return false;
}

template <class M>
constexpr bool declares_compact_spheres_only() {
  if constexpr (requires { M::compact_spheres_only; }) return M::compact_spheres_only;
  return false;
}

template <class... M>
class MechanismSet {
 public:
  static constexpr std::size_t size = sizeof...(M);
  static std::vector<std::string_view> registered_names() { return {M::name...}; }
  static std::vector<std::string_view> standalone_names() {
    std::vector<std::string_view> v;
    ((declares_standalone<M>() ? v.push_back(M::name) : void()), ...);
    return v;
  }
  static std::vector<std::string_view> brownian_term_names() {
    std::vector<std::string_view> v;
    ((declares_brownian_term<M>() ? v.push_back(M::name) : void()), ...);
    return v;
  }

  static std::vector<std::string_view> compact_spheres_only_names() {
    std::vector<std::string_view> v;
    ((declares_compact_spheres_only<M>() ? v.push_back(M::name) : void()), ...);
    return v;
  }

  MechanismSet(const std::vector<std::string>& names, const KernelSettings& s, const Gas& gas, const Sound& sound)
      : m_(M(s, gas, sound)...) {
    const std::vector<std::string_view> known = registered_names();
    for (const std::string& n : names) {
      std::size_t k = 0;
      while (k < size && known[k] != n) ++k;
      if (k == size) throw_unknown_mechanism(n, known);
      on_[k] = true;
    }
    for (std::size_t k = 0; k < size; ++k)
      if (on_[k]) active_.push_back(k);
    each([&](const auto& m, std::size_t) {
      const KernelNeeds nd = m.needs();
      needs_.distance = needs_.distance || nd.distance;
      needs_.thermal_speed = needs_.thermal_speed || nd.thermal_speed;
      needs_.volume = needs_.volume || nd.volume;
    });
  }

  const KernelNeeds& needs() const { return needs_; }
  std::vector<std::string_view> names() const {
    std::vector<std::string_view> v;
    each([&](const auto& m, std::size_t) { v.push_back(m.name); });
    return v;
  }
  double beta(const SampleSet& p, std::size_t i, std::size_t j, double r) const {
    double b = 0.0;
    each([&](const auto& m, std::size_t) { b += m.beta(p, i, j, r); });
    return b;
  }
  double bound(const SampleSet& p, std::size_t i, const CellBounds& cb) const {
    double b = 0.0;
    each([&](const auto& m, std::size_t) { b += m.bound(p, i, cb); });
    return b;
  }
  double bound_cell(const CellBounds& cb) const {
    double b = 0.0;
    each([&](const auto& m, std::size_t) { b += m.bound_cell(cb); });
    return b;
  }
  std::size_t active() const { return active_.size(); }
  void prepare(CellBounds& cb) const {
    each([&](const auto& m, std::size_t) {
      if constexpr (requires { m.prepare(cb); }) m.prepare(cb);
    });
  }
  double beta_of(std::size_t k, const SampleSet& p, std::size_t i, std::size_t j, double r) const {
    double b = 0.0;
    each([&](const auto& m, std::size_t pos) {
      if (pos == active_[k]) b = m.beta(p, i, j, r);
    });
    return b;
  }
  // bound_pair of every switched-on mechanism, in order, into out[0 .. active()).
  void bound_pair_all(const CellBounds& a, const CellBounds& b, double* out) const {
    std::size_t k = 0;
    each([&](const auto& m, std::size_t) { out[k++] = m.bound_pair(a, b); });
  }

 private:
  // f(mechanism, index) for every switched-on mechanism, in list order.
  template <class F>
  void each(F&& f) const {
    [&]<std::size_t... K>(std::index_sequence<K...>) {
      ((on_[K] ? f(std::get<K>(m_), K) : void()), ...);
    }(std::index_sequence_for<M...>{});
  }
  std::tuple<M...> m_;
  std::array<bool, size> on_{};
  std::vector<std::size_t> active_;  // registry positions of the switched-on mechanisms
  KernelNeeds needs_;
};

}  // namespace agglo::acoustics
