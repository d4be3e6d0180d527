#include "agglo/electrostatics/sphere_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace agglo::es {

UnitSphereMesh icosphere(int level) {
  UnitSphereMesh m;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const Vec3 v0[12] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                       {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& v : v0) m.vertices.push_back(v / norm(v));
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int k = 0; k < level; ++k) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      Vec3 p = m.vertices[a] + m.vertices[b];
      m.vertices.push_back(p / norm(p));
      int id = static_cast<int>(m.vertices.size()) - 1;
      mid.emplace(key, id);
      return id;
    };
    std::vector<std::array<int, 3>> next;
    next.reserve(m.triangles.size() * 4);
    for (const auto& tr : m.triangles) {
      int a = midpoint(tr[0], tr[1]), b = midpoint(tr[1], tr[2]), c = midpoint(tr[2], tr[0]);
      next.push_back({tr[0], a, c});
      next.push_back({tr[1], b, a});
      next.push_back({tr[2], c, b});
      next.push_back({a, b, c});
    }
    m.triangles = std::move(next);
  }
  return m;
}

namespace {
int vertices_at(int level) { return 10 * (1 << (2 * level)) + 2; }
}  // namespace

int icosphere_level_for(int n) {
  int k = 0;
  while (k < 6 && vertices_at(k) < n) ++k;
  return k;
}

int icosphere_vertices_for(int n) { return vertices_at(icosphere_level_for(n)); }

}  // namespace agglo::es
