#pragma once
// Working cluster of the builders: centres and radii, with the point-mass centroid and squared radius
// of gyration (every primary weighted equally, structure/observables.hpp), and the overlap test of a
// new primary against the cluster.
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/structure/aggregate.hpp"

namespace agglo::structure {

struct Cluster {
  std::vector<Vec3> x;
  std::vector<double> r;
  std::size_t size() const { return x.size(); }
  void add(const Vec3& p, double radius) {
    x.push_back(p);
    r.push_back(radius);
  }
  Vec3 centroid() const;
  double rg2(const Vec3& cm) const;  // (1/n) sum |x_i - cm|^2
  // True when a sphere (p, radius) overlaps a primary by more than rounding (1e-10 of the contact distance).
  bool overlaps(const Vec3& p, double radius) const;
  void append(const Cluster& o);
};

// The cluster moved so that its centroid is at the origin.
Aggregate centred_aggregate(const Cluster& c);

}  // namespace agglo::structure
