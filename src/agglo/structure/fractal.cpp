#include "agglo/structure/fractal.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "agglo/core/cancel.hpp"
#include "agglo/core/constants.hpp"
#include "agglo/core/rng.hpp"
#include "agglo/structure/cluster.hpp"
#include "agglo/structure/geometry.hpp"
#include "agglo/structure/primaries.hpp"

namespace agglo::structure {

namespace {

constexpr std::uint64_t kFractalStream = 0x46524143;  // "FRAC"
constexpr int kAngleTries = 8;
constexpr long kMaxPairDraws = 200L * kMaxPairTries;  // random (i, j) draws of one join

struct Law {
  double kf, df, abar;
  double rg(double n) const { return law_radius_of_gyration(n, kf, df, abar); }
};

// Squared centroid distance that gives the union of (m1, rg1sq) and (m2, rg2sq) the law's R_g.
double gamma_squared(double m1, double rg1sq, double m2, double rg2sq, const Law& law) {
  const double M = m1 + m2, rt = law.rg(M);
  return M / (m1 * m2) * (M * rt * rt - m1 * rg1sq - m2 * rg2sq);
}

std::size_t random_index(CounterRng& rng, std::size_t n) {
  return std::min(n - 1, static_cast<std::size_t>(rng.uniform() * static_cast<double>(n)));
}

// Tunable PCA step: the monomer of radius r at distance Gamma from the centroid, touching one primary.
bool add_monomer(Cluster& c, double r, const Law& law, CounterRng& rng) {
  const Vec3 cm = c.centroid();
  const double n1 = static_cast<double>(c.size());
  const double g2 = gamma_squared(n1, c.rg2(cm), 1.0, 0.0, law);
  if (!(g2 > 0.0)) return false;
  const double gamma = std::sqrt(g2);
  std::vector<std::size_t> cand;
  for (std::size_t j = 0; j < c.size(); ++j)
    if (std::abs(norm(c.x[j] - cm) - gamma) <= r + c.r[j]) cand.push_back(j);
  while (!cand.empty()) {
    const std::size_t pick = random_index(rng, cand.size());
    const std::size_t j = cand[pick];
    for (int t = 0; t < kAngleTries; ++t) {
      const auto p = sphere_intersection_point(cm, gamma, c.x[j], r + c.r[j], 2.0 * constants::pi * rng.uniform());
      if (p && !c.overlaps(*p, r)) {
        c.add(*p, r);
        return true;
      }
    }
    cand.erase(cand.begin() + static_cast<std::ptrdiff_t>(pick));
  }
  return false;
}

// A sub-cluster of the given radii by tunable PCA, from a touching dimer; false when stuck.
bool grow_subcluster(Cluster& c, const double* radii, int m, const Law& law, CounterRng& rng) {
  c = Cluster{};
  c.add({}, radii[0]);
  if (m > 1) c.add(random_direction(rng) * (radii[0] + radii[1]), radii[1]);
  for (int k = 2; k < m; ++k)
    if (!add_monomer(c, radii[k], law, rng)) return false;
  return true;
}

struct JoinGeometry {
  Vec3 cm1, cm2;
  std::vector<double> d1, d2;
  double gamma;
};

// Range of the distance D = |x_i - centroid 2| that pair (i, j) allows; empty when lo > hi.
std::pair<double, double> pair_range(const JoinGeometry& g, double d1, double d2, double s) {
  return {std::max(std::abs(g.gamma - d1), std::abs(d2 - s)), std::min(g.gamma + d1, d2 + s)};
}

// One placement of cluster b for the touching pair (i, j); false when it overlaps cluster a.
bool try_place(const Cluster& a, const Cluster& b, std::size_t i, std::size_t j, const JoinGeometry& g,
               CounterRng& rng, Cluster& placed) {
  const double d1 = g.d1[i], d2 = g.d2[j], s = a.r[i] + b.r[j];
  const auto [lo, hi] = pair_range(g, d1, d2, s);
  const double D = lo + (hi - lo) * rng.uniform();
  const Vec3 e1 = d1 > 0.0 ? (a.x[i] - g.cm1) / d1 : random_direction(rng);
  const double cos_t = d1 > 0.0 ? std::clamp((d1 * d1 + g.gamma * g.gamma - D * D) / (2.0 * d1 * g.gamma), -1.0, 1.0)
                                : 1.0;
  Vec3 p, q;
  orthonormal_pair(e1, p, q);
  const double phi = 2.0 * constants::pi * rng.uniform(), sin_t = std::sqrt(1.0 - cos_t * cos_t);
  const Vec3 c2 = g.cm1 + g.gamma * (cos_t * e1 + sin_t * (std::cos(phi) * p + std::sin(phi) * q));
  Vec3 xj = c2;
  if (d2 > 0.0) {
    const auto hit = sphere_intersection_point(a.x[i], s, c2, d2, 2.0 * constants::pi * rng.uniform());
    if (!hit) return false;
    xj = *hit;
  }
  Rotation R = random_rotation(rng);
  if (d2 > 0.0) {
    const Vec3 u = (xj - c2) / d2;
    R = compose(rotation_taking((b.x[j] - g.cm2) / d2, u), rotation_about(u, 2.0 * constants::pi * rng.uniform()));
  }
  placed = Cluster{};
  for (std::size_t k = 0; k < b.size(); ++k) {
    const Vec3 y = k == j ? xj : c2 + R.apply(b.x[k] - g.cm2);
    if (a.overlaps(y, b.r[k])) return false;
    placed.add(y, b.r[k]);
  }
  return true;
}

// Tunable CCA: joins b to a (a grows); false when no pair of kMaxPairTries placed b.
bool join_clusters(Cluster& a, const Cluster& b, const Law& law, CounterRng& rng) {
  JoinGeometry g;
  g.cm1 = a.centroid();
  g.cm2 = b.centroid();
  const double g2 = gamma_squared(static_cast<double>(a.size()), a.rg2(g.cm1), static_cast<double>(b.size()),
                                  b.rg2(g.cm2), law);
  if (!(g2 > 0.0)) return false;
  g.gamma = std::sqrt(g2);
  for (const auto& x : a.x) g.d1.push_back(norm(x - g.cm1));
  for (const auto& x : b.x) g.d2.push_back(norm(x - g.cm2));
  // Touching pairs are drawn at random (no list of all m1 m2 pairs); a drawn pair that cannot span
  // Gamma costs only the draw.
  Cluster placed;
  int feasible = 0;
  for (long draw = 0; draw < kMaxPairDraws && feasible < kMaxPairTries; ++draw) {
    const std::size_t i = random_index(rng, a.size()), j = random_index(rng, b.size());
    const auto [lo, hi] = pair_range(g, g.d1[i], g.d2[j], a.r[i] + b.r[j]);
    if (lo > hi) continue;
    ++feasible;
    poll_cancel();  // a placement costs O(m1 + m2): a cancelled build stops here (core/cancel.hpp)
    for (int k = 0; k < kAngleTries; ++k)
      if (try_place(a, b, i, j, g, rng, placed)) {
        a.append(placed);
        return true;
      }
  }
  return false;
}

std::string df_text(const FractalRequest& q) {
  return fmt::format("D_f = {:g} with k_f = {:g}", q.fractal_dimension, q.fractal_prefactor);
}

std::vector<Cluster> grow_subclusters(const FractalRequest& q, const std::vector<double>& radii, const Law& law,
                                      CounterRng& rng) {
  const int n = q.primaries;
  const int count = (n + kSubclusterSize - 1) / kSubclusterSize;
  std::vector<Cluster> out(static_cast<std::size_t>(count));
  int start = 0;
  for (int s = 0; s < count; ++s) {
    const int m = n / count + (s < n % count ? 1 : 0);  // sizes differ by at most one
    std::vector<double> r(radii.begin() + start, radii.begin() + start + m);
    int tries = 0;
    poll_cancel();
    while (!grow_subcluster(out[static_cast<std::size_t>(s)], r.data(), m, law, rng)) {
      for (int k = m - 1; k > 0; --k)  // a restart takes the primaries in another order
        std::swap(r[static_cast<std::size_t>(k)], r[random_index(rng, static_cast<std::size_t>(k) + 1)]);
      if (++tries >= kMaxRestarts)
        throw BuildError("fractal_dimension",
                         fmt::format("particle-cluster aggregation cannot reach {} for {} primaries: no placement "
                                     "after {} restarts (try a D_f nearer 1.8 or another k_f)",
                                     df_text(q), m, kMaxRestarts));
    }
    start += m;
  }
  return out;
}

}  // namespace

double law_radius_of_gyration(double n, double k_f, double d_f, double abar) {
  return abar * std::pow(n / k_f, 1.0 / d_f);
}

Aggregate build_fractal(const FractalRequest& q) {
  if (q.primaries < 2) throw BuildError("primaries", "a fractal aggregate needs at least 2 primaries");
  if (!(q.fractal_dimension >= kMinFractalDimension && q.fractal_dimension <= kMaxFractalDimension))
    throw BuildError("fractal_dimension", fmt::format("the tunable PCA/CCA method reaches D_f in [{:g}, {:g}] only",
                                                      kMinFractalDimension, kMaxFractalDimension));
  CounterRng rng(q.seed, kFractalStream, 0);
  const auto radii = primary_radii(q.primaries, q.radius, q.radius_std, rng);
  const Law law{q.fractal_prefactor, q.fractal_dimension, geometric_mean(radii)};
  auto level = grow_subclusters(q, radii, law, rng);
  while (level.size() > 1) {
    std::vector<Cluster> next;
    for (std::size_t k = 0; k + 1 < level.size(); k += 2) {
      if (!join_clusters(level[k], level[k + 1], law, rng))
        throw BuildError("fractal_dimension",
                         fmt::format("cluster-cluster aggregation cannot reach {}: no placement of clusters of {} "
                                     "and {} primaries after {} touching pairs",
                                     df_text(q), level[k].size(), level[k + 1].size(), kMaxPairTries));
      next.push_back(std::move(level[k]));
    }
    if (level.size() % 2 == 1) next.push_back(std::move(level.back()));
    level = std::move(next);
  }
  return centred_aggregate(level.front());
}

}  // namespace agglo::structure
