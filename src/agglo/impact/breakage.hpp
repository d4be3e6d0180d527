#pragma once
// Breakage observables of one impact (docs/model.md §A.7), from the agglomerate at the launch (relaxed,
// its first n_agg particles; the projectile, if any, is not part of it) and the final particle state:
//   fragments:            components of the final contact graph (all particles, as classify() counts
//                         them), each counted by its agglomerate primaries; components without any are
//                         dropped (a lone projectile). Sizes largest first, and the distribution
//                         counts[s - 1] = fragments of s primaries, s = 1 .. largest;
//   largest fraction:     largest fragment / n_agg [1];
//   damage ratio:         contacts between agglomerate primaries at the launch that are not active at
//                         the end / contacts at the launch [1];
//   restructuring:        point-mass R_g (structure/observables.hpp) and mean coordination (contacts
//                         per primary among the primaries) of the agglomerate at the launch and of the
//                         largest fragment at the end [m], [1];
//   wall impacts:         a fragment is on the wall when one of its particles is in contact with a
//                         wall at the end; the impact rebounded when some fragment off the wall moves
//                         away from it (centre-of-mass velocity . wall normal > 0), else it stuck;
//                         rebound kinetic energy = sum over the particles of those fragments of
//                         (1/2) m |v|^2 [J], also as a fraction of the impact kinetic energy (that of the
//                         agglomerate at the launch speed).
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/dem/dem_system.hpp"

namespace agglo::impact {

using ContactEdge = std::pair<std::uint32_t, std::uint32_t>;

// The active contacts (i < j) among the first n particles of `sys`, sorted.
std::vector<ContactEdge> contact_edges(const dem::DemSystem& sys, std::size_t n);

// Connected components of the graph of n nodes and `edges`, each sorted, ordered by their least node.
std::vector<std::vector<int>> graph_components(std::size_t n, const std::vector<ContactEdge>& edges);

enum class WallOutcome { none = -1, stuck = 0, rebounded = 1 };

struct Breakage {
  std::vector<int> fragment_sizes;      // primaries per fragment, largest first
  std::vector<int> size_counts;         // [s - 1]: fragments of s primaries
  double largest_fraction = 1.0;        // [1]
  int initial_contacts = 0;             // contacts among the primaries at the launch
  int broken_contacts = 0;              // of those, not active at the end
  double damage_ratio = 0.0;            // broken / initial [1]
  double rg_before = 0.0, rg_after = 0.0;                    // point-mass R_g [m]
  double coordination_before = 0.0, coordination_after = 0.0;  // mean contacts per primary [1]
  WallOutcome wall = WallOutcome::none;
  double rebound_kinetic = 0.0;         // [J]
  double impact_kinetic = 0.0;          // [J]
  double rebound_fraction = 0.0;        // rebound / impact kinetic energy [1]
};

// Fragments, damage and restructuring. `before`: the agglomerate at the launch (n_agg = before.size()
// primaries) and its contacts `edges_before`; `after`: every particle at the end (the first n_agg are
// the primaries) and all active contacts `edges_after` (i < j, sorted, as contact_edges gives them).
Breakage measure_breakage(const dem::Particles& before, const std::vector<ContactEdge>& edges_before,
                          const dem::Particles& after, const std::vector<ContactEdge>& edges_after);

// Sticking or rebound at a wall of unit `normal` (towards the particles); `on_wall[k]` = particle k touches
// a wall at the end; `impact_kinetic` [J] as defined above.
void measure_rebound(Breakage& b, const dem::Particles& after, const std::vector<ContactEdge>& edges_after,
                     const std::vector<char>& on_wall, const Vec3& normal, double impact_kinetic);

}  // namespace agglo::impact
