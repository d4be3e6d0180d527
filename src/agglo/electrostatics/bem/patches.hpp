#pragma once
// Near-uniform surface patches on a sphere: the Fibonacci (golden-angle) lattice, n points with
// z_k = 1 - (2k+1)/n and azimuth k * pi (3 - sqrt 5); every patch is given the equal area
// 4 pi R^2 / n (Swinbank & Purser 2006; Gonzalez 2010). Returns unit vectors (outward normals).
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::es::bem {
std::vector<Vec3> fibonacci_sphere(int n);
}  // namespace agglo::es::bem
