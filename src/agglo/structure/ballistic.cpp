#include "agglo/structure/ballistic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "agglo/core/cancel.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/rng.hpp"
#include "agglo/structure/cluster.hpp"
#include "agglo/structure/geometry.hpp"
#include "agglo/structure/primaries.hpp"

namespace agglo::structure {

namespace {

constexpr std::uint64_t kBallisticStream = 0x42414c4c;  // "BALL"

// Radius of the sphere about cm that encloses every primary.
double enclosing_radius(const Cluster& c, const Vec3& cm) {
  double R = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) R = std::max(R, norm(c.x[k] - cm) + c.r[k]);
  return R;
}

// A straight line of isotropic direction u whose start o lies `reach` outside the enclosing sphere,
// crossing the disk of radius `reach` about cm at a uniform random point.
void random_line(const Vec3& cm, double reach, CounterRng& rng, Vec3& o, Vec3& u) {
  u = random_direction(rng);
  Vec3 p, q;
  orthonormal_pair(u, p, q);
  const double b = reach * std::sqrt(rng.uniform()), phi = 2.0 * constants::pi * rng.uniform();
  o = cm - 2.0 * reach * u + b * (std::cos(phi) * p + std::sin(phi) * q);
}

[[noreturn]] void too_many_misses() {
  throw BuildError("primaries", "ballistic aggregation: no hit after kMaxMisses random lines");
}

void add_ballistic_primary(Cluster& c, double r, CounterRng& rng) {
  const Vec3 cm = c.centroid();
  const double reach = enclosing_radius(c, cm) + r;
  for (int miss = 0; miss < kMaxMisses; ++miss) {
    Vec3 o, u;
    random_line(cm, reach, rng, o, u);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < c.size(); ++j)
      if (const auto t = ray_sphere_hit(o, u, c.x[j], r + c.r[j])) best = std::min(best, *t);
    if (best < std::numeric_limits<double>::infinity()) {
      c.add(o + best * u, r);
      return;
    }
  }
  too_many_misses();
}

// Moves a randomly rotated b along a random line until it first touches a; a grows.
void collide_clusters(Cluster& a, const Cluster& b, CounterRng& rng) {
  const Vec3 ca = a.centroid(), cb = b.centroid();
  const Rotation R = random_rotation(rng);
  const double reach = enclosing_radius(a, ca) + enclosing_radius(b, cb);
  for (int miss = 0; miss < kMaxMisses; ++miss) {
    poll_cancel();  // a line costs O(m_a m_b): a cancelled build stops here (core/cancel.hpp)
    Vec3 o, u;
    random_line(ca, reach, rng, o, u);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec3 y = o + R.apply(b.x[j] - cb);
      for (std::size_t i = 0; i < a.size(); ++i)
        if (const auto t = ray_sphere_hit(y, u, a.x[i], a.r[i] + b.r[j])) best = std::min(best, *t);
    }
    if (best < std::numeric_limits<double>::infinity()) {
      for (std::size_t j = 0; j < b.size(); ++j) a.add(o + R.apply(b.x[j] - cb) + best * u, b.r[j]);
      return;
    }
  }
  too_many_misses();
}

}  // namespace

Aggregate build_ballistic(const BallisticRequest& q) {
  if (q.primaries < 2) throw BuildError("primaries", "a ballistic aggregate needs at least 2 primaries");
  CounterRng rng(q.seed, kBallisticStream, q.kind == Ballistic::particle_cluster ? 0 : 1);
  const auto radii = primary_radii(q.primaries, q.radius, q.radius_std, rng);
  if (q.kind == Ballistic::particle_cluster) {
    Cluster c;
    c.add({}, radii[0]);
    for (std::size_t k = 1; k < radii.size(); ++k) {
      poll_cancel();  // a primary costs O(k) per line (core/cancel.hpp)
      add_ballistic_primary(c, radii[k], rng);
    }
    return centred_aggregate(c);
  }
  std::vector<Cluster> level(radii.size());
  for (std::size_t k = 0; k < radii.size(); ++k) level[k].add({}, radii[k]);
  while (level.size() > 1) {
    std::vector<Cluster> next;
    for (std::size_t k = 0; k + 1 < level.size(); k += 2) {
      collide_clusters(level[k], level[k + 1], rng);
      next.push_back(std::move(level[k]));
    }
    if (level.size() % 2 == 1) next.push_back(std::move(level.back()));
    level = std::move(next);
  }
  return centred_aggregate(level.front());
}

}  // namespace agglo::structure
