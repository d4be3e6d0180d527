#pragma once
// An aggregate of spherical primaries (docs/model.md §S): centres x [m], radii r [m], and per primary an
// optional charge [C], relative permittivity, material name and density (empty vectors = not given). Primaries "touch" when their
// centre distance equals r_i + r_j within kContactTolerance of the smaller radius; the builders of this
// folder place every primary touching at least one other, with no overlap (structure/validate.hpp).
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::structure {

// Contact distance tolerance: |d_ij - (r_i + r_j)| <= kContactTolerance min(r_i, r_j) is a contact,
// d_ij < r_i + r_j - kContactTolerance min(r_i, r_j) an overlap.
inline constexpr double kContactTolerance = 1e-6;

struct Aggregate {
  std::vector<Vec3> x;              // centres [m]
  std::vector<double> r;            // radii [m]
  std::vector<double> charge;       // [C], empty = none given
  std::vector<double> permittivity; // relative permittivity, empty = none given
  std::vector<std::string> material; // material name per primary (impact cases), empty = none given
  std::vector<double> density;       // [kg/m^3] of each primary's material, empty = none given
  std::size_t size() const { return x.size(); }
  void add(const Vec3& pos, double radius) {
    x.push_back(pos);
    r.push_back(radius);
  }
};

// A request the method cannot meet. `key` is the leaf name of the [agglomerate] setting at fault
// ("fractal_dimension", "primaries", "file", ...), so the settings layer names key and value.
struct BuildError : std::invalid_argument {
  BuildError(std::string key_, const std::string& what) : std::invalid_argument(what), key(std::move(key_)) {}
  std::string key;
};

}  // namespace agglo::structure
