#include "agglo/structure/validate.hpp"

#include <cmath>

#include <fmt/format.h>

namespace agglo::structure {

namespace {

void check_primaries(const Aggregate& a, const std::string& key) {
  if (a.size() < 2) throw BuildError(key, fmt::format("an aggregate needs at least 2 primaries, got {}", a.size()));
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!isfinite(a.x[k]) || !(a.r[k] > 0.0) || !std::isfinite(a.r[k]))
      throw BuildError(key, fmt::format("primary {} needs a finite position and a radius > 0", k));
}

}  // namespace

Contacts validate_structure(const Aggregate& a, const std::string& key) {
  check_primaries(a, key);
  auto scan = scan_contacts(a);
  if (scan.overlap)
    throw BuildError(key, fmt::format("primaries {} and {} overlap by {:.3g} of the smaller radius (allowed: {:g}); "
                                      "touching primaries sit at centre distance r_i + r_j",
                                      scan.oi, scan.oj, scan.overlap_depth, kContactTolerance));
  const std::size_t parts = connected_components(a.size(), scan.contacts.pairs);
  if (parts > 1) {
    std::size_t lone = 0;
    while (lone < a.size() && scan.contacts.coordination[lone] > 0) ++lone;
    throw BuildError(key, fmt::format("the primaries form {} disconnected groups (contact: |d - r_i - r_j| <= {:g} of "
                                      "the smaller radius){}",
                                      parts, kContactTolerance,
                                      lone < a.size() ? fmt::format("; primary {} touches none", lone) : ""));
  }
  return std::move(scan.contacts);
}

}  // namespace agglo::structure
