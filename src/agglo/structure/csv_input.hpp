#pragma once
// Aggregate from CSV text (docs/model.md §S.5): a header line naming the columns, then one primary per
// line. Required columns x, y, z, radius [m]; optional charge [C], permittivity (relative) and material
// (a name, resolved by the impact case against its [[materials]]); other
// columns (e.g. coordination, as agglo aggregate writes it) are ignored. Lines starting with '#' and
// blank lines are skipped. The structure is then checked by validate_structure (validate.hpp).
#include <istream>
#include <string>

#include "agglo/structure/aggregate.hpp"

namespace agglo::structure {

inline constexpr std::size_t kMaxFilePrimaries = 10000;  // as agglomerate.primaries

// BuildError(key) naming `source` and the line on a missing column, a non-number, a short row or more
// than kMaxFilePrimaries primaries.
Aggregate read_aggregate_csv(std::istream& in, const std::string& source, const std::string& key);

}  // namespace agglo::structure
