#pragma once
// Checkpoint payload of a collision run (agglo collide --checkpoint; docs/restart.md, "Collide"): the complete
// impact::ImpactState written field by field (no struct padding, so equal states give equal bytes).
#include "agglo/impact/impact_state.hpp"
#include "agglo/io/checkpoint.hpp"

namespace agglo::io {

// Layout version of the payload; a payload of another layout is refused.
inline constexpr std::uint64_t kImpactPayloadLayout = 1;

void write_impact_state(CheckpointWriter& w, const impact::ImpactState& s);
// ConfigError naming the file when the payload is of another layout or malformed.
impact::ImpactState read_impact_state(CheckpointReader& r);

}  // namespace agglo::io
