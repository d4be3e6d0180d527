#pragma once
// Unit icosphere (subdivided icosahedron) used to place output samples on sphere surfaces.
// Level k has 10*4^k + 2 vertices and 20*4^k triangles (k = 3: 642 / 1280).
#include <array>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::es {

struct UnitSphereMesh {
  std::vector<Vec3> vertices;               // unit vectors
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

UnitSphereMesh icosphere(int level);

// Smallest level whose vertex count is >= n (capped at 6).
int icosphere_level_for(int n);

// Vertices of the icosphere icosphere_level_for(n) picks: 10*4^k + 2.
int icosphere_vertices_for(int n);

}  // namespace agglo::es
