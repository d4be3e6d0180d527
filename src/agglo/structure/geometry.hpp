#pragma once
// Geometry helpers of the builders: isotropic random directions and rotations drawn from a CounterRng
// (Rotation, rotation_about, compose: core/rotation.hpp),
// the circle where two spheres meet, and the first contact of a sphere moving along a straight line.
#include <optional>

#include "agglo/core/rng.hpp"
#include "agglo/core/rotation.hpp"
#include "agglo/core/vec3.hpp"

namespace agglo::structure {

Vec3 random_direction(CounterRng& rng);                  // uniform on the unit sphere
Rotation random_rotation(CounterRng& rng);               // uniform (Haar) random rotation
Rotation rotation_taking(const Vec3& from, const Vec3& to);    // smallest rotation taking unit `from` to unit `to`
// Two unit vectors p, q completing unit n to a right-handed orthonormal basis.
void orthonormal_pair(const Vec3& n, Vec3& p, Vec3& q);

// A point of the circle where sphere (c1, R1) meets sphere (c2, R2), at azimuth phi; none if they do
// not meet. The point is at distance R1 from c1 and R2 from c2 to rounding.
std::optional<Vec3> sphere_intersection_point(const Vec3& c1, double R1, const Vec3& c2, double R2, double phi);

// Smallest t >= 0 at which a point o + t u (unit u) reaches distance s from c; none if it passes by.
std::optional<double> ray_sphere_hit(const Vec3& o, const Vec3& u, const Vec3& c, double s);

}  // namespace agglo::structure
