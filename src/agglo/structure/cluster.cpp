#include "agglo/structure/cluster.hpp"

namespace agglo::structure {

Vec3 Cluster::centroid() const {
  Vec3 s;
  for (const auto& p : x) s += p;
  return s / static_cast<double>(x.size());
}

double Cluster::rg2(const Vec3& cm) const {
  double s = 0.0;
  for (const auto& p : x) s += dot(p - cm, p - cm);
  return s / static_cast<double>(x.size());
}

bool Cluster::overlaps(const Vec3& p, double radius) const {
  constexpr double kRoundingMargin = 1.0 - 2e-10;  // squared-distance margin, 1e-10 of the distance
  for (std::size_t k = 0; k < x.size(); ++k) {
    const Vec3 d = p - x[k];
    const double s = radius + r[k];
    if (dot(d, d) < s * s * kRoundingMargin) return true;
  }
  return false;
}

void Cluster::append(const Cluster& o) {
  x.insert(x.end(), o.x.begin(), o.x.end());
  r.insert(r.end(), o.r.begin(), o.r.end());
}

Aggregate centred_aggregate(const Cluster& c) {
  Aggregate a;
  const Vec3 cm = c.centroid();
  for (std::size_t k = 0; k < c.size(); ++k) a.add(c.x[k] - cm, c.r[k]);
  return a;
}

}  // namespace agglo::structure
