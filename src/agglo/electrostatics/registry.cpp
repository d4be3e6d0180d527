#include "agglo/electrostatics/registry.hpp"

#include <deque>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/electrostatics/bem/bem_solver.hpp"
#include "agglo/electrostatics/coulomb_solver.hpp"
#include "agglo/electrostatics/spectral/spectral_solver.hpp"

namespace agglo::es {

namespace {

struct Registry {
  Registry() : types{coulomb_solver_type(), spectral_solver_type(), bem_solver_type()} {}
  std::mutex mutex;
  std::deque<SolverType> types;  // a deque: references stay valid when a type is added
};

Registry& registry() {
  static Registry r;
  return r;
}

const SolverType* find(const Registry& r, std::string_view name) {
  for (const auto& t : r.types)
    if (t.name == name) return &t;
  return nullptr;
}

std::string quoted_names(const Registry& r) {
  std::string s;
  for (const auto& t : r.types) s += fmt::format("{}\"{}\"", s.empty() ? "" : ", ", t.name);
  return s;
}

}  // namespace

bool register_solver(SolverType type) {
  auto& r = registry();
  std::lock_guard lock(r.mutex);
  if (type.make == nullptr) throw std::logic_error(fmt::format("electrostatic solver \"{}\" has no maker", type.name));
  if (find(r, type.name)) throw std::logic_error(fmt::format("electrostatic solver \"{}\" registered twice", type.name));
  r.types.push_back(std::move(type));
  return true;
}

const SolverType& solver_type(std::string_view name) {
  auto& r = registry();
  std::lock_guard lock(r.mutex);
  if (const SolverType* t = find(r, name)) return *t;
  throw ConfigError(fmt::format("unknown electrostatic solver \"{}\" (allowed: {})", name, quoted_names(r)));
}

std::vector<std::string> solver_names() {
  auto& r = registry();
  std::lock_guard lock(r.mutex);
  std::vector<std::string> out;
  for (const auto& t : r.types) out.emplace_back(t.name);
  return out;
}

std::unique_ptr<Solver> make_solver(const SolverOptions& opt) { return solver_type(opt.solver).make(opt); }

}  // namespace agglo::es
