// Breakage observables of one impact (breakage.hpp).
#include "agglo/impact/breakage.hpp"

#include <algorithm>
#include <numeric>

#include "agglo/structure/observables.hpp"

namespace agglo::impact {

std::vector<ContactEdge> contact_edges(const dem::DemSystem& sys, std::size_t n) {
  std::vector<ContactEdge> e;
  for (const auto& pr : sys.pairs())
    if (pr.state.active && pr.i < n && pr.j < n) e.emplace_back(std::min(pr.i, pr.j), std::max(pr.i, pr.j));
  std::sort(e.begin(), e.end());
  return e;
}

std::vector<std::vector<int>> graph_components(std::size_t n, const std::vector<ContactEdge>& edges) {
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (const auto& [i, j] : edges) parent[find(static_cast<int>(i))] = find(static_cast<int>(j));
  std::vector<std::vector<int>> groups;
  std::vector<int> slot(n, -1);
  for (int k = 0; k < static_cast<int>(n); ++k) {
    const int r = find(k);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[slot[r]].push_back(k);
  }
  return groups;
}

namespace {

// Point-mass R_g and mean coordination of the primaries `members` with the contacts `edges` among them.
std::pair<double, double> shape_of(const dem::Particles& p, const std::vector<int>& members,
                                   const std::vector<ContactEdge>& edges) {
  structure::Aggregate a;
  std::vector<char> in(p.size(), 0);
  for (int k : members) {
    a.add(p.x[k], p.r[k]);
    in[k] = 1;
  }
  const auto inside = std::count_if(edges.begin(), edges.end(), [&](const ContactEdge& e) { return in[e.first] && in[e.second]; });
  const double n = static_cast<double>(members.size());
  return {structure::rg_point_mass(a), n > 0 ? 2.0 * static_cast<double>(inside) / n : 0.0};
}

}  // namespace

Breakage measure_breakage(const dem::Particles& before, const std::vector<ContactEdge>& edges_before,
                          const dem::Particles& after, const std::vector<ContactEdge>& edges_after) {
  Breakage b;
  const std::size_t n_agg = before.size();
  std::vector<int> largest;
  for (auto& g : graph_components(after.size(), edges_after)) {
    std::erase_if(g, [&](int k) { return static_cast<std::size_t>(k) >= n_agg; });
    if (g.empty()) continue;
    b.fragment_sizes.push_back(static_cast<int>(g.size()));
    if (g.size() > largest.size()) largest = std::move(g);
  }
  std::sort(b.fragment_sizes.begin(), b.fragment_sizes.end(), std::greater<>());
  if (!b.fragment_sizes.empty()) {
    b.size_counts.assign(static_cast<std::size_t>(b.fragment_sizes.front()), 0);
    for (int s : b.fragment_sizes) ++b.size_counts[static_cast<std::size_t>(s - 1)];
    b.largest_fraction = static_cast<double>(b.fragment_sizes.front()) / static_cast<double>(n_agg);
  }
  b.initial_contacts = static_cast<int>(edges_before.size());
  for (const auto& e : edges_before)
    if (!std::binary_search(edges_after.begin(), edges_after.end(), e)) ++b.broken_contacts;
  b.damage_ratio = b.initial_contacts > 0 ? static_cast<double>(b.broken_contacts) / b.initial_contacts : 0.0;
  std::vector<int> all(n_agg);
  std::iota(all.begin(), all.end(), 0);
  std::tie(b.rg_before, b.coordination_before) = shape_of(before, all, edges_before);
  std::tie(b.rg_after, b.coordination_after) = shape_of(after, largest, edges_after);
  return b;
}

void measure_rebound(Breakage& b, const dem::Particles& after, const std::vector<ContactEdge>& edges_after,
                     const std::vector<char>& on_wall, const Vec3& normal, double impact_kinetic) {
  b.wall = WallOutcome::stuck;
  b.rebound_kinetic = 0.0;
  b.impact_kinetic = impact_kinetic;
  for (const auto& g : graph_components(after.size(), edges_after)) {
    double m = 0.0, ke = 0.0;
    Vec3 mv;
    bool touching = false;
    for (int k : g) {
      touching = touching || on_wall[k];
      m += after.m[k];
      mv += after.m[k] * after.v[k];
      ke += 0.5 * after.m[k] * norm2(after.v[k]);
    }
    if (touching || !(dot(mv / m, normal) > 0.0)) continue;
    b.wall = WallOutcome::rebounded;
    b.rebound_kinetic += ke;
  }
  b.rebound_fraction = impact_kinetic > 0.0 ? b.rebound_kinetic / impact_kinetic : 0.0;
}

}  // namespace agglo::impact
