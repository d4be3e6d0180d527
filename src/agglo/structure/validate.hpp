#pragma once
// The check every structure passes, generated or read from a file (docs/model.md §S.4): no pair
// overlaps by more than kContactTolerance of the smaller radius, every primary touches (centre distance
// r_i + r_j within kContactTolerance min(r_i, r_j)) and the contact graph is connected. At least two
// primaries, finite positions, positive radii.
#include <string>

#include "agglo/structure/observables.hpp"

namespace agglo::structure {

// The contacts; BuildError(key) with a one-line reason (the first overlap, or the primaries that no
// contact path joins to primary 0) otherwise.
Contacts validate_structure(const Aggregate& a, const std::string& key);

}  // namespace agglo::structure
