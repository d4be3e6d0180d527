#pragma once
// Checkpoint payload of a collision run, owned by the impact engine (agglo collide --checkpoint; docs/restart.md, "Collide"): the complete
// impact::ImpactState written field by field (no struct padding, so equal states give equal bytes).
#include "agglo/impact/impact_state.hpp"
#include "agglo/io/checkpoint.hpp"

namespace agglo::impact {

// Layout version of the payload; a payload of another layout is refused.
inline constexpr std::uint64_t kImpactPayloadLayout = 3;  // 2: + the launch agglomerate; 3: + material ids

void write_impact_state(io::CheckpointWriter& w, const ImpactState& s);
// ConfigError naming the file when the payload is of another layout or malformed.
ImpactState read_impact_state(io::CheckpointReader& r);

}  // namespace agglo::impact
