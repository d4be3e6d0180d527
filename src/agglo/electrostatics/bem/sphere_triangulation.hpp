#pragma once
// Triangulation of points on the unit sphere by their 3D convex hull. For points on a sphere the
// hull is the spherical Delaunay triangulation; applied to the Fibonacci patch centres
// (patches.hpp) it turns the BEM surface samples into a closed triangle mesh (2n - 4 triangles).
// Incremental hull with conflict lists (expected O(n log n)); triangles are counter-clockwise seen
// from outside (normal (b - a) x (c - a) points away from the sphere centre).
#include <array>
#include <span>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::es::bem {

// Convex hull of unit vectors (|p| = 1, the sphere centred at the origin): every input point is a
// hull vertex except duplicates of another point (to round-off), which are left out.
// Throws std::invalid_argument for fewer than 4 points or when all points are coplanar.
std::vector<std::array<int, 3>> sphere_convex_hull(std::span<const Vec3> unit_points);

// Hull of fibonacci_sphere(n), computed once per n and cached (thread safe); n >= 4.
const std::vector<std::array<int, 3>>& fibonacci_sphere_triangles(int n);

}  // namespace agglo::es::bem
