#pragma once
// Agglomerates from the structure builder (docs/model.md §S): agglomerate.shape = fractal, bpca, bcca
// (structure/fractal.hpp, structure/ballistic.hpp) or file (structure/csv_input.hpp). The structure is
// built and checked (structure/validate.hpp) when the case is parsed; a request the method cannot meet,
// or a file whose primaries overlap or do not touch, is a ConfigError naming the key and value.
// As the target of an impact, the touching structure is scaled about its centroid by
//   s = 1 - delta0(abar) / (2 abar),  delta0 = JKR equilibrium overlap of two primaries of radius abar,
// so that every contact starts at the JKR equilibrium overlap (exact for equal primaries; for lognormal
// radii the overlap of a contact is (r_i + r_j)(1 - s), near its own delta0, and the DEM settles the rest).
// Charges: the file's charge column when present; otherwise agglomerate.charged gives primary k the
// charge (-1)^k sigma_f 4 pi r_k^2 (alternating by index, as the built-in shapes). Permittivity: the
// file's column when present, otherwise agglomerate.permittivity.
#include <string_view>

#include "agglo/core/config.hpp"
#include "agglo/dem/contact_params.hpp"
#include "agglo/dem/particles.hpp"
#include "agglo/impact/impact_case.hpp"

namespace agglo::impact {

bool is_structure_shape(std::string_view shape);  // fractal, bpca, bcca, file

// The keys that choose and build a structure: [agglomerate]'s or [projectile]'s.
struct StructureKeys {
  const settings::Setting& shape;
  const settings::BuilderKeys& builder;
};

// Reads the keys of the shape from [agglomerate], builds or reads the structure
// into a.structure and checks it. `case_file`: relative agglomerate.file paths start from its folder.
void parse_structure(const ConfigSection& ag, const std::string& case_file, AgglomerateSpec& a);
// The same from the section `sec` with `keys` (an aggregate projectile: [projectile]).
void parse_structure(const ConfigSection& sec, const std::string& case_file, AgglomerateSpec& a,
                     const StructureKeys& keys);

// The structure of a generated shape (fractal, bpca, bcca) from a's request (primaries, D_f, k_f, radius,
// radius_std, seed); structure::BuildError when the method cannot meet it.
structure::Aggregate build_structure(const AgglomerateSpec& a);

// Appends the structure's primaries to p, scaled to the JKR equilibrium overlap (above; delta0 of the
// material of a's first primary), with the materials and densities of c.
void place_structure(const AgglomerateSpec& a, const ImpactCase& c, dem::Particles& p);

}  // namespace agglo::impact
