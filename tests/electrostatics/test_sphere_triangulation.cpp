// Convex-hull triangulation of the Fibonacci patch centres (bem/sphere_triangulation.hpp) and the
// BEM solver's surface_triangles().
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "agglo/core/constants.hpp"
#include "agglo/electrostatics/bem/bem_solver.hpp"
#include "agglo/electrostatics/bem/patches.hpp"
#include "agglo/electrostatics/bem/sphere_triangulation.hpp"

using namespace agglo;
using namespace agglo::es;
using constants::pi;

namespace {

// Topology and geometry checks of a closed, outward-oriented triangulation of the unit sphere;
// returns the total area of the flat triangles.
double check_sphere_mesh(const std::vector<Vec3>& p, const std::vector<std::array<int, 3>>& tri) {
  const int n = static_cast<int>(p.size());
  EXPECT_EQ(tri.size(), static_cast<std::size_t>(2 * n - 4)) << "n = " << n;
  std::map<std::pair<int, int>, int> directed;  // directed edge -> number of triangles using it
  std::vector<int> used(n, 0);
  double area = 0.0;
  for (const auto& t : tri) {
    for (int e = 0; e < 3; ++e) {
      EXPECT_GE(t[e], 0);
      EXPECT_LT(t[e], n);
      if (t[e] < 0 || t[e] >= n) return 0.0;
      ++used[t[e]];
      ++directed[{t[e], t[(e + 1) % 3]}];
    }
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
    const Vec3 nrm = cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
    const Vec3 centroid = (p[t[0]] + p[t[1]] + p[t[2]]) / 3.0;
    EXPECT_GT(dot(nrm, centroid), 0.0) << "inward triangle " << t[0] << " " << t[1] << " " << t[2];
    area += 0.5 * norm(nrm);
  }
  // Each directed edge used once and its reverse used once: every undirected edge is shared by
  // exactly two triangles with opposite orientation.
  std::size_t undirected = 0;
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << e.first << "->" << e.second;
    const auto rev = directed.find({e.second, e.first});
    EXPECT_TRUE(rev != directed.end()) << "edge " << e.first << "-" << e.second << " has one triangle";
    if (e.first < e.second) ++undirected;
  }
  EXPECT_EQ(directed.size(), 2 * undirected);
  const long V = n, E = static_cast<long>(undirected), F = static_cast<long>(tri.size());
  EXPECT_EQ(V - E + F, 2) << "n = " << n;
  for (int i = 0; i < n; ++i) EXPECT_GT(used[i], 0) << "point " << i << " unused";
  return area;
}

}  // namespace

TEST(SphereTriangulation, FibonacciHullIsClosedOutwardAndConverges) {
  double prev_err = 1.0;
  for (const int n : {4, 12, 100, 2000}) {
    const std::vector<Vec3> p = bem::fibonacci_sphere(n);
    const auto tri = bem::sphere_convex_hull(p);
    const double area = check_sphere_mesh(p, tri);
    const double err = (4.0 * pi - area) / (4.0 * pi);
    EXPECT_GT(err, 0.0) << "n = " << n << ": inscribed polyhedron area must be below 4 pi";
    EXPECT_LT(err, prev_err) << "n = " << n;
    prev_err = err;
  }
  EXPECT_LT(prev_err, 5e-3);  // n = 2000: relative area error ~ 2 pi / n
}

TEST(SphereTriangulation, CachedPerPatchCount) {  // (its speed is a benchmark's business, not a test's)
  const auto tri = bem::sphere_convex_hull(bem::fibonacci_sphere(2000));
  const auto& a = bem::fibonacci_sphere_triangles(2000);
  const auto& b = bem::fibonacci_sphere_triangles(2000);
  EXPECT_EQ(&a, &b);
  EXPECT_EQ(a, tri);
  EXPECT_EQ(bem::fibonacci_sphere_triangles(100).size(), 196u);
}

TEST(SphereTriangulation, RejectsTooFewOrCoplanarPoints) {
  const std::vector<Vec3> three{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_THROW(bem::sphere_convex_hull(three), std::invalid_argument);
  const double c = std::sqrt(0.5);
  const std::vector<Vec3> equator{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {c, c, 0}};
  EXPECT_THROW(bem::sphere_convex_hull(equator), std::invalid_argument);
}

TEST(SphereTriangulation, BemSurfaceTrianglesCoverEveryBody) {
  constexpr int n = 300;
  constexpr double R = 10e-6;
  SolverOptions o;
  o.solver = "bem";
  o.patches_per_sphere = n;
  o.matvec = "direct";
  auto solver = make_bem_solver(o);
  EXPECT_TRUE(solver->surface_triangles().empty());  // no solve yet: no samples
  Problem prob;
  prob.spheres = {Sphere{{0, 0, 0}, R, 1e-14, 10}, Sphere{{2.5 * R, 0, 0}, R, -1e-14, 10}};
  solver->solve(prob);
  const auto s = solver->surface();
  const auto tri = solver->surface_triangles();
  ASSERT_EQ(s.size(), static_cast<std::size_t>(2 * n));
  ASSERT_EQ(tri.size(), static_cast<std::size_t>(2 * (2 * n - 4)));
  for (const auto& t : tri) {
    for (const int v : t) {
      ASSERT_GE(v, 0);
      ASSERT_LT(v, 2 * n);
    }
    // All three vertices on one body, and the triangle faces away from that body's centre.
    const int b = s[t[0]].body;
    EXPECT_EQ(s[t[1]].body, b);
    EXPECT_EQ(s[t[2]].body, b);
    const Vec3 c = prob.spheres[b].center;
    const Vec3 nrm = cross(s[t[1]].position - s[t[0]].position, s[t[2]].position - s[t[0]].position);
    EXPECT_GT(dot(nrm, (s[t[0]].position + s[t[1]].position + s[t[2]].position) / 3.0 - c), 0.0);
  }
}
